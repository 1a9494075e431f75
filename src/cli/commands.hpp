#pragma once
// Sub-commands of the stcontact program (INTERFACE.md "Command line").
#include <optional>
#include <string>
#include <vector>

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
};

/// Prints the model's sizes; returns the exit status.
int runCheck(const CheckArgs& args);
/// Solves and writes the outputs; returns 0 converged, 2 not converged.
int runSolve(const SolveArgs& args);

}  // namespace stc::cli
