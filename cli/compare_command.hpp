#pragma once
// stcontact compare SCENE: a work-precision comparison of solution strategies (docs/compare.md).
#include <optional>
#include <string>
#include <vector>

#include "src/problem/problem.hpp"
#include "src/report/comparison.hpp"
#include "src/scene/scene.hpp"

namespace CLI {
class App;
}

namespace stc::cli {

struct CompareArgs {
  std::string scene;
  std::string solvers;                 ///< comma-separated; empty: every available strategy
  std::optional<std::string> out;      ///< default results/<scene name>/compare
  int repeats = 3;                     ///< timed runs per strategy (medians over them)
  std::vector<std::string> overrides;  ///< --set section.key=value
  std::optional<double> tolerance;     ///< on the error estimate; default the scene's
  bool quiet = false;
};

/// The comma-separated strategy names of --solvers (empty: availableSolvers()); InputError for
/// an empty, unknown, unavailable or repeated name.
std::vector<std::string> solverList(const std::string& list);

/// The comparison's description before its runs: scene, sizes, command, machine and build.
Comparison describeComparison(const std::string& scene_file, const std::string& command, const Scene& scene,
                              const Problem& problem, int repeats);

/// Declares the sub-command and its options on `app`, filling `args`.
CLI::App* addCompareCommand(CLI::App& app, CompareArgs& args);

/// Runs the comparison and writes the report; returns 0 once it is written (a strategy that does not
/// converge is a result of the comparison, reported in its summary, not a failure).
int runCompare(const CompareArgs& args);

}  // namespace stc::cli
