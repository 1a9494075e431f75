// stcontact solve SCENE: choose the solver, compute the incremental reference for the true error
// (scenes small enough unless --no-reference, any size with --reference), solve, write every output file.
#include <chrono>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "stcontact/cli/commands.hpp"
#include "stcontact/cli/stopping_help.hpp"
#include "stcontact/cli/terminal_progress.hpp"
#include "stcontact/cli/threads_option.hpp"
#include "stcontact/core/clock.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/core/memory.hpp"
#include "stcontact/core/interruption.hpp"
#include "stcontact/io/atomic_file.hpp"
#include "stcontact/io/run_folder.hpp"
#include "stcontact/io/run_writer.hpp"
#include "stcontact/linalg/ranks.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/strategies/registry.hpp"
#include "stcontact/studies/reference.hpp"
#include "stcontact/studies/solve_on_ranks.hpp"
#include "stcontact/studies/solve_options.hpp"
#include "stcontact/version.hpp"

namespace stc::cli {
namespace {

std::unique_ptr<ErrorReference> referenceOrWarning(const Problem& problem, TerminalProgress& progress,
                                                   PreparedOperators& operators) {
  std::string warning;
  std::unique_ptr<ErrorReference> reference;
  {
    const RunProgress run(&progress, "reference (incremental)");
    reference = solveReference(problem, run.callback(), warning, operators, run.phaseNote());
  }
  if (!warning.empty()) {
    std::cerr << "warning: " << warning << std::endl;
    progress.record("warning: " + warning);
  }
  return reference;
}

// The outputs rank 0 writes (studies/solve_on_ranks.hpp), the note said on the terminal and in run.log.
OutputSpec outputsOf(const Scene& scene, const Ranks& ranks, const SolveResult& result, TerminalProgress& progress) {
  std::string note;
  OutputSpec output = outputsOnRanks(scene, ranks, result, note);
  if (!note.empty()) progress.note(note);
  return output;
}

// The solve; a space-time strategy hands its displacement history in separated form when frames
// are written (they come from it, no solve in the writer).
SolveResult runSolver(const Problem& problem, const Scene& scene, const ErrorReference* reference,
                      TerminalProgress& progress, PreparedOperators& operators, const OutputSpec& output) {
  const RunProgress run(&progress, std::string(scene.solver.name()));
  SolveInputs inputs;
  inputs.reference = reference;
  inputs.converged_lambda = reference ? &reference->referenceForces() : nullptr;
  inputs.callback = run.callback();
  inputs.phase_note = run.phaseNote();
  inputs.spatial_modes = false;  // not written
  inputs.separated_displacement = output.frames;
  inputs.operators = &operators;
  return solve(problem, scene.solver, inputs);
}

}  // namespace

CLI::App* addSolveCommand(CLI::App& app, SolveArgs& args) {
  auto* cmd = app.add_subcommand("solve", "solve a scene and write the results");
  cmd->add_option("scene", args.scene, "scene file (TOML)")->required();
  cmd->add_option("--solver", args.solver,
                  "latin | latin-pgd | fas-aposteriori | fas-apriori | incremental (default: the scene's "
                  "[solver] name, else fas-apriori)");
  cmd->add_option("--out", args.out, "output folder (default results/<scene name>/<solver>)");
  cmd->add_option("--tol", args.tolerance, toleranceHelp());
  cmd->add_option("--max-iterations", args.max_iterations, maxIterationsHelp());
  cmd->add_option("--set", args.overrides, "override a scene value: section.key=value")->take_all();
  cmd->add_flag("--quiet", args.quiet, "no progress, no final report");
  cmd->add_flag("--no-reference", args.no_reference,
                "do not compute the incremental reference (no true error in history.csv)");
  cmd->add_flag("--reference", args.reference,
                "compute the incremental reference (the true error in history.csv) whatever the size "
                "(default: at most " + std::to_string(kMaxReferenceContactNodes) + " contact nodes)")
      ->excludes("--no-reference");
  addThreadsOption(*cmd);
  addProgressIntervalOption(*cmd);
  return cmd;
}

namespace {

// The lines, each ended by a newline (a line that has its own keeps it).
std::string joinedLines(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line.empty() || line.back() != '\n' ? line + "\n" : line;
  return text;
}

// The final report: how the solve ended, its figures, and the whole run's time beside the solver's
// (what a user waited: the set-up, the reference and the writing too).
std::string finalReport(const std::string& solver, const SolveSummary& s, const std::filesystem::path& out,
                        double run_s, std::optional<double> reference_s, double write_s) {
  std::ostringstream text;
  text << solver << ": " << toString(s.termination) << " — " << s.message << "\n"
       << "  iterations " << s.iterations << ", indicator " << s.indicator;
  if (s.error) text << ", true error " << *s.error;
  text << ", " << s.wall_s << " s solving\n  the whole run " << std::setprecision(3) << run_s << " s (";
  if (reference_s) text << "reference " << *reference_s << " s, ";
  text << "writing " << write_s << " s)\n  results in " << out.string() << "/\n";
  return text.str();
}

}  // namespace

int runSolve(const SolveArgs& args) {
  const auto started = std::chrono::steady_clock::now();
  const Scene scene = readScene(args.scene, withSolverOptions(args.overrides, args.solver, args.tolerance, args.max_iterations));
  const std::string solver(scene.solver.name());
  const std::filesystem::path out = args.out ? std::filesystem::path(*args.out)
                                             : std::filesystem::path("results") / scene.name / solver;
  const Problem problem = buildProblem(scene);  // bad input stops here, before anything is created
  const LinearSolverOptions linear = scene.solver.linearAtTolerance();
  const Ranks ranks = currentRanks();
  requireBackendForRanks(scene, ranks);
  std::optional<RunFolder> folder;  // rank 0's: checked and locked before the solve, written after
  if (ranks.writes()) folder.emplace(out);

  TerminalProgress progress(args.quiet || !ranks.writes());
  // each operator prepared once, by the scene's backend: the reference, the solve, the frames
  PreparedOperators operators(linear);
  std::unique_ptr<ErrorReference> reference;
  std::optional<double> reference_s;
  const ReferenceWish wish = args.no_reference ? ReferenceWish::Never
                             : args.reference   ? ReferenceWish::Always
                                                : ReferenceWish::UpToMaxNodes;
  if (computesReference(problem, scene.solver.strategy, wish)) {
    const auto begun = std::chrono::steady_clock::now();
    reference = referenceOrWarning(problem, progress, operators);
    reference_s = secondsSince(begun);
  }
  const SolveResult result = runSolver(problem, scene, reference.get(), progress, operators, scene.output);
  throwIfInterrupted();  // a solve stopped by a signal writes nothing
  std::vector<double> peaks = valuesOfEveryRank(peakResidentBytes());  // every rank takes part
  if (!ranks.writes()) return result.summary.converged() ? 0 : 2;
  const OutputSpec output = outputsOf(scene, ranks, result, progress);
  if (output.frames) progress.note("writing " + out.string() + "/ with its frames");
  const auto writing = std::chrono::steady_clock::now();
  writeRunOutputs(folder->path(), problem, result,
                  {scene.parameters_json, STC_VERSION, std::move(peaks), started, reference_s, scene.model_json},
                  output, operators);
  const std::string report =
      finalReport(solver, result.summary, out, secondsSince(started), reference_s, secondsSince(writing));
  progress.record(report);
  writeFileAtomically(folder->path() / "run.log", joinedLines(progress.lines()));  // what the terminal showed
  folder->commit();
  if (!args.quiet) std::cout << report;
  return result.summary.converged() ? 0 : 2;
}

}  // namespace stc::cli
