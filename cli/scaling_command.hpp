#pragma once
// stcontact scaling SCENE: the comparison of strategies over a mesh series and a time series, with
// growth exponents, crossover against the incremental solver and memory (docs/scaling.md).
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace stc::cli {

struct ScalingArgs {
  std::string scene;
  std::optional<std::string> solvers;         ///< comma-separated; absent: every available strategy
  std::optional<std::string> out;             ///< default results/<scene name>/scaling
  int repeats = 3;                            ///< timed runs per strategy and size (medians over them)
  /// Mesh series, at the scene's instants: --arc-nodes 101,201,... for half_disc and half_disc_slab
  /// scenes (default 101,201,401,801), --divisions 8,12,... for half_ball ones (default 6,8,12);
  /// "none": no series. The option of the other generator is refused.
  std::vector<std::string> arc_nodes;
  std::vector<std::string> divisions;
  /// Time series, at the scene's mesh (--steps 201,801,...; "none": no series).
  std::vector<std::string> steps = {"201", "801", "2001"};
  double target_error = 1e-4;                 ///< true error whose time is measured
  /// Indicator tolerance: low, so that no iterative strategy stops on its indicator before the
  /// target error (the runs stop at the target anyway, so it costs nothing when reached).
  double tolerance = 1e-8;
  std::optional<int> max_iterations;          ///< default: the scene's [solver] max_iterations
  std::optional<double> time_cap_s;           ///< per error run; default none
  /// --only-at-tolerance: no first-reach runs (error run, timed repeats), the solves at tolerance only.
  bool only_at_tolerance = false;
  std::vector<std::string> overrides;         ///< --set section.key=value, for every size
  bool quiet = false;
};

/// Declares the sub-command and its options on `app`, filling `args`.
CLI::App* addScalingCommand(CLI::App& app, ScalingArgs& args);

/// Runs the study and writes the report; returns 0 once it is written (a strategy that does not
/// reach the target at some size is a result, not a failure).
int runScaling(const ScalingArgs& args);

}  // namespace stc::cli
