#pragma once
// stcontact compare SCENE: a work-precision comparison of solution strategies (docs/compare.md).
#include <optional>
#include <string>
#include <vector>

#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene.hpp"
#include "stcontact/studies/compare_runs.hpp"

namespace CLI {
class App;
}

namespace stc::cli {

struct CompareArgs {
  std::string scene;
  std::optional<std::string> solvers;  ///< comma-separated; absent: every available strategy
  std::optional<std::string> out;      ///< default results/<scene name>/compare
  int repeats = 3;                     ///< timed runs per strategy (medians over them)
  std::vector<std::string> overrides;  ///< --set section.key=value
  std::optional<double> tolerance;     ///< on the error estimate; default the scene's
  bool quiet = false;
};

/// Declares the sub-command and its options on `app`, filling `args`.
CLI::App* addCompareCommand(CLI::App& app, CompareArgs& args);

/// Runs the comparison and writes the report; returns 0 once it is written (a strategy that does not
/// converge is a result of the comparison, reported in its summary, not a failure).
int runCompare(const CompareArgs& args);

}  // namespace stc::cli
