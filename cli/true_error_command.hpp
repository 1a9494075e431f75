#pragma once
// stcontact true-error SCENE --solution RUN/solution.h5: the true error of a solution already
// written (docs/interface.md, "`true-error`"), measured on one process against the
// incremental reference of the same scene. A run on ranks or on an iterative backend, where the
// reference would cost more than the run, gets its true error afterwards from a direct factor.
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace stc::cli {

struct TrueErrorArgs {
  std::string scene;
  std::string solution;                ///< --solution: the run's solution.h5
  std::vector<std::string> overrides;  ///< --set section.key=value: the run's, [solver] and [output] aside
  bool quiet = false;
};

/// Declares the sub-command and its options on `app`, filling `args`.
CLI::App* addTrueErrorCommand(CLI::App& app, TrueErrorArgs& args);

/// Measures and prints the true error; returns 0 once measured, 2 when the reference did not converge.
int runTrueError(const TrueErrorArgs& args);

}  // namespace stc::cli
