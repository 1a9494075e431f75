// stcontact compare SCENE: every strategy asked for (default: availableSolvers()) solves the
// scene `--repeats` times; the incremental reference, computed once, gives every iteration its true
// error. Writes, each atomically, into --out: work_precision.csv, summary.csv, summary.md and, through
// gnuplot, three PNG plots. docs/compare.md describes every file and how time and memory are measured.
#include "stcontact/cli/compare_command.hpp"
#include "stcontact/cli/stopping_help.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <sstream>

#include "stcontact/cli/commands.hpp"
#include "stcontact/cli/terminal_progress.hpp"
#include "stcontact/cli/threads_option.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/core/interruption.hpp"
#include "stcontact/io/run_folder.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/strategies/registry.hpp"
#include "stcontact/studies/compare_plots.hpp"
#include "stcontact/studies/compare_runs.hpp"
#include "stcontact/studies/comparison_writer.hpp"
#include "stcontact/studies/number_format.hpp"

namespace stc::cli {
namespace {

std::string commandLine(const CompareArgs& a, const std::vector<Strategy>& solvers,
                        const std::filesystem::path& out) {
  std::string line = "stcontact compare " + a.scene + " --solvers " + joinedNames(solvers) + " --out " + out.string() +
                     " --repeats " + std::to_string(a.repeats);
  for (const auto& o : a.overrides) line += " --set " + o;
  if (a.tolerance) line += " --tol " + shortNumber(*a.tolerance, 6);
  return line;
}

std::string strategyLine(const StrategyMeasurement& m) {
  const StrategySummary s = summarize(m);
  std::string line = "  " + m.solver + ": " + toString(m.termination) + ", median " + shortNumber(s.median_total_s, 3) + " s";
  for (const Reach& r : s.reaches)
    line += ", " + targetLabel(r.target) + " " + (r.wall_s ? shortNumber(*r.wall_s, 3) + " s" : "not reached");
  return line;
}

}  // namespace

CLI::App* addCompareCommand(CLI::App& app, CompareArgs& args) {
  auto* cmd = app.add_subcommand("compare", "work-precision comparison of strategies (docs/compare.md)");
  cmd->add_option("scene", args.scene, "scene file (TOML)")->required();
  cmd->add_option("--solvers", args.solvers, "comma-separated strategies (default: every available one)");
  cmd->add_option("--out", args.out, "report folder (default results/<scene name>/compare)");
  cmd->add_option("--repeats", args.repeats, "timed runs per strategy, medians over them")->capture_default_str();
  cmd->add_option("--set", args.overrides, "override a scene value: section.key=value")->take_all();
  cmd->add_option("--tol", args.tolerance, toleranceHelp());
  cmd->add_flag("--quiet", args.quiet, "no progress, no final report");
  addThreadsOption(*cmd);
  addProgressIntervalOption(*cmd);
  return cmd;
}

int runCompare(const CompareArgs& args) {
  if (args.repeats < 1) throw InputError("--repeats must be >= 1");
  Scene scene = readScene(args.scene, args.overrides);
  const std::vector<Strategy> solvers = solverList(args.solvers);
  if (args.tolerance) {
    if (!(*args.tolerance > 0.0)) throw InputError("--tol must be > 0");
    scene.solver.setTolerance(*args.tolerance);
  }
  const std::filesystem::path out =
      args.out ? std::filesystem::path(*args.out) : std::filesystem::path("results") / scene.name / "compare";
  RunFolder folder(out);  // checked and locked before the runs, written whole after them
  const Problem problem = buildProblem(scene);
  Comparison comparison = describeComparison(args.scene, commandLine(args, solvers, out), scene, problem, args.repeats);

  TerminalProgress progress(args.quiet);
  const ReferenceSolution reference = computeReference(problem, &progress);
  comparison.reference_s = reference.total_s;
  const CompareContext context{problem, scene.solver, reference, args.repeats, &progress};
  for (const Strategy solver : solvers) {
    comparison.strategies.push_back(measureStrategy(solver, context));
    progress.note(strategyLine(comparison.strategies.back()));
  }
  comparison.memory_method = describeMemoryMethod(comparison.strategies.front().memory.since_reset);
  comparison.load_after = loadAverage();
  throwIfInterrupted();
  writeComparison(folder.path(), comparison);

  std::string warning;
  if (!drawWorkPrecisionPlots(folder.path(), comparison, warning))
    std::cerr << "warning: " << folder.named(warning) << std::endl;
  folder.commit();
  if (!args.quiet) std::cout << "report: " << (out / "summary.md").string() << std::endl;
  return 0;
}

}  // namespace stc::cli
