#pragma once
// The runs of `stcontact compare` (and of the Python module's compare): each strategy's error run and
// timed repeats through the registry (strategies/registry.hpp), with the peak memory of the strategy's runs.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene.hpp"
#include "stcontact/studies/comparison.hpp"
#include "stcontact/studies/progress.hpp"
#include "stcontact/studies/reference.hpp"

namespace stc {

/// Where the runs of an iterative strategy may stop before the solver does (stcontact scaling,
/// docs/scaling.md); none by default (stcontact compare runs every solve to its end).
struct EarlyStop {
  /// The error run stops at its first record with true error <= target; the timed runs at the same
  /// iteration, so the work to reach the target is measured and nothing after it. A strategy whose
  /// error run ends without reaching the target gets no timed run (it reached nothing to time).
  std::optional<double> target_error;
  /// The error run stops once its solver has run this long (seconds, error evaluation included).
  std::optional<double> time_cap_s;
};

struct CompareContext {
  const Problem& problem;
  const SolverSpec& spec;
  const ReferenceSolution& reference;
  int repeats = 3;
  ProgressReporter* progress = nullptr;  ///< shows each run (none: nothing shown)
  EarlyStop stop = {};
  /// Called after every record of every run (error and timed); false stops that run, like a
  /// solver's callback (the Python module's Ctrl-C and per-iteration callback). None by default.
  IterationCallback keep_going = {};
};

/// The comma-separated strategy names of a comparison (`--solvers`, Python's solvers=; absent:
/// every strategy); InputError for an empty list or an empty, unknown, unavailable or repeated name.
std::vector<Strategy> solverList(const std::optional<std::string>& list);

/// The comparison's description before its runs: scene, sizes, command, machine and build.
Comparison describeComparison(const std::string& scene_file, const std::string& command, const Scene& scene,
                              const Problem& problem, int repeats);

/// One error run (iterative strategies only), then `repeats` timed runs; see docs/compare.md. With
/// an EarlyStop, the message says where and why the error run was stopped.
StrategyMeasurement measureStrategy(Strategy strategy, const CompareContext& context);

/// Each of `strategies` solved at `tolerance` as a user runs it (context.spec with that tolerance, no
/// early stop), context.repeats rounds with the strategies alternated within each; the true error of
/// the first round's last iterate against the reference. In the order of `strategies`.
std::vector<SolveAtTolerance> measureAtTolerance(const std::vector<Strategy>& strategies, const CompareContext& context,
                                                 double tolerance);

}  // namespace stc
