#pragma once
// Sub-commands of the stcontact program (docs/interface.md "Command line").
#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene.hpp"
#include "stcontact/solver/solve_summary.hpp"

namespace stc::cli {

struct CheckArgs {
  std::string scene;
  std::vector<std::string> overrides;
};

struct SolveArgs {
  std::string scene;
  std::optional<std::string> solver;
  std::optional<std::string> out;
  std::optional<double> tolerance;
  std::optional<int> max_iterations;
  std::vector<std::string> overrides;
  bool quiet = false;
  bool no_reference = false;
  bool reference = false;  ///< --reference: the incremental reference whatever the size
};

struct SvdArgs {
  std::string scene;
  std::vector<std::string> overrides;
  std::optional<std::string> out;
  int modes = 10;                       ///< pairs written to the per-mode files and tables
  std::string solver = "incremental";   ///< the only one accepted: the analysis of the exact solution
};

// Each sub-command is declared on the program by its addXCommand, which fills its arguments, and run
// by its runX, which returns the exit status (docs/interface.md "Exit status"); cli/main.cpp lists
// them. The commands that solve also take --threads and --progress-interval.

CLI::App* addCheckCommand(CLI::App& app, CheckArgs& args);
CLI::App* addSolveCommand(CLI::App& app, SolveArgs& args);
CLI::App* addSvdCommand(CLI::App& app, SvdArgs& args);

/// Prints the model's sizes; returns the exit status.
int runCheck(const CheckArgs& args);
/// Solves and writes the outputs; returns 0 converged, 2 not converged.
int runSolve(const SolveArgs& args);
/// A posteriori space-time SVD of the incremental solution (docs/method.md §3); returns 0, or 2 if the
/// solve did not converge (nothing written).
int runSvd(const SvdArgs& args);

}  // namespace stc::cli
