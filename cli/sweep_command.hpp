#pragma once
// stcontact sweep SCENE --set-range KEY=FROM:TO:COUNT: one scene solved for every value of one key,
// each warm-started from the previous value's solution, and (unless --no-independent) cold, so that
// the report gives the sweep's total cost both ways (docs/sweep.md).
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace stc::cli {

struct SweepArgs {
  std::string scene;
  std::string range;                   ///< KEY=FROM:TO:COUNT (src/scene/sweep_range.hpp)
  std::optional<std::string> solver;   ///< default: the scene's [solver] name
  std::vector<std::string> overrides;  ///< --set section.key=value, for every value
  std::optional<std::string> out;      ///< default results/<scene name>/sweep_<KEY>
  std::optional<double> tolerance;     ///< on the error estimate; default the scene's
  bool no_independent = false;         ///< warm solves only (no cold solve of each value)
  bool write_solutions = false;        ///< each value's warm solution as `solve` writes it
  bool quiet = false;
};

/// Declares the sub-command and its options on `app`, filling `args`.
CLI::App* addSweepCommand(CLI::App& app, SweepArgs& args);

/// Validates every value (scene and problem) before writing anything, runs the sweep and writes the
/// report; returns 0 when every solve converged, 2 when one did not (the report is still written).
int runSweep(const SweepArgs& args);

}  // namespace stc::cli
