// stcontact true-error: the true error of docs/method.md §2,
//   e² = Σ_k (u_k − u_ref,k)ᵀ K (u_k − u_ref,k) / Σ_k u_ref,kᵀ K u_ref,k,
// of the contact forces a run wrote (solution.h5's /interface/force, its equilibrated iterate), against
// the incremental reference solved here (src/incremental/error_reference.hpp), beside the estimate the
// run stopped on. Nothing is written: the figures are printed.
#include "stcontact/cli/true_error_command.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

#include "stcontact/cli/terminal_progress.hpp"
#include "stcontact/cli/threads_option.hpp"
#include "stcontact/core/interruption.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/studies/number_format.hpp"
#include "stcontact/studies/reference.hpp"

namespace stc::cli {
namespace {

std::string scientific(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6e", x);
  return text;
}

// The report: the true error, then what the run said of itself (its estimate, and its own true error
// when it measured one).
std::string report(const StoredSolutionError& measured) {
  const StoredSolution& stored = measured.stored;
  const double error = measured.error;
  std::string text = "true error " + scientific(error) + " (" + stored.solver + "'s solution in " + stored.file +
                     ", against the incremental reference; measured in " + shortNumber(measured.seconds, 3) + " s)\n";
  if (std::isfinite(stored.error_estimate)) {
    text += "  the run's estimate " + scientific(stored.error_estimate);
    if (error > 0.0) text += ": " + shortNumber(stored.error_estimate / error, 3) + " times the true error";
    text += "\n";
  }
  if (std::isfinite(stored.error)) text += "  the run's own true error " + scientific(stored.error) + "\n";
  return text;
}

}  // namespace

CLI::App* addTrueErrorCommand(CLI::App& app, TrueErrorArgs& args) {
  auto* cmd = app.add_subcommand(
      "true-error", "the true error of a run's solution.h5 against the incremental reference, on one process");
  cmd->add_option("scene", args.scene, "the scene file the run solved (TOML)")->required();
  cmd->add_option("--solution", args.solution, "the run's solution.h5")->required();
  cmd->add_option("--set", args.overrides,
                  "override a scene value: section.key=value (the run's; [solver] ones set the reference's solve)")
      ->take_all();
  cmd->add_flag("--quiet", args.quiet, "no progress");
  addThreadsOption(*cmd);
  addProgressIntervalOption(*cmd);
  return cmd;
}

int runTrueError(const TrueErrorArgs& args) {
  const Scene scene = readScene(args.scene, args.overrides);
  const Problem problem = buildProblem(scene);
  PreparedOperators operators(scene.solver.linearAtTolerance());
  TerminalProgress progress(args.quiet);
  std::string warning;
  std::optional<StoredSolutionError> measured;
  {
    const RunProgress run(&progress, "reference (incremental)");
    measured = measureStoredSolution(problem, scene.model_json, args.solution, operators, run.callback(), warning,
                                     run.phaseNote());
  }
  throwIfInterrupted();
  if (!measured) {
    std::cerr << warning << std::endl;
    return 2;
  }
  std::cout << report(*measured);
  return 0;
}

}  // namespace stc::cli
