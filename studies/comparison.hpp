#pragma once
// A comparison of solution strategies on one scene (`stcontact compare`, docs/compare.md): what was measured
// for each strategy, and the per-strategy statistics of the report (medians over repeats of the
// work needed to first reach true errors 1e-2, 1e-4, 1e-6; docs/method.md §2 error).
#include <optional>
#include <string>
#include <vector>

#include "stcontact/studies/peak_memory.hpp"
#include "stcontact/studies/run_environment.hpp"
#include "stcontact/studies/work_precision.hpp"

namespace stc {

/// The true errors the report asks each strategy to reach.
const std::vector<double>& targetErrors();

/// A solve at tolerance τ as a user runs it (`stcontact solve --tol τ`): it stops on its own estimate,
/// timed from the call (set-up included), the strategies alternated within each round of repeats.
struct SolveAtTolerance {
  double tolerance = 0.0;
  Termination termination = Termination::MaxIterations;
  int relaxations = 0;
  int sparse_solves = 0;
  long long krylov_iterations = 0;  ///< of its linear solves (0 on a direct backend)
  std::string incremental_form;  ///< the incremental solver's form, "interface" or "whole-body" (empty for the others)
  double error_estimate = 0.0;   ///< the estimate it stopped on
  std::optional<double> error;   ///< true error of its last iterate against the reference
  std::vector<double> times_s;   ///< one per repeat
  double median_s = 0.0;
  MemoryUse memory;              ///< the run with the largest peak (the probe reset before each run)
};

/// Everything measured for one strategy.
struct StrategyMeasurement {
  std::string solver;
  /// The exact (incremental) solver: error 0 by construction, one point per run.
  bool reference_point = false;
  std::vector<TimedRun> runs;  ///< repeats 1 … N, timed without measuring the error
  Termination termination = Termination::MaxIterations;
  std::string message;
  int iterations = 0;
  int relaxations = 0;
  double indicator = 0.0;
  /// The estimate the strategy stopped on (+∞ when it never had one; 0 for the exact reference).
  double final_error_estimate = 0.0;
  /// Right-hand sides solved with a sparse factor by the whole solve (SolveSummary::sparseSolves).
  int sparse_solves = 0;
  /// True error at termination of a solve that stopped on its own estimate at the tolerance: what a
  /// user gets from `stcontact solve --tol`.
  std::optional<double> final_error;
  /// Smallest true error of the error run (how close a strategy came to a target it did not reach).
  std::optional<double> best_error;
  /// The extra run that measured the true error at every iteration (its time is not in the report's).
  std::optional<double> error_run_s;
  /// False when a timed run did not repeat the error run's iterations (the errors it lacks stay empty).
  bool errors_matched = true;
  /// Cost of an input the strategy needs and the comparison provides (fas-aposteriori's converged
  /// solution), not included in its times.
  std::optional<double> prerequisite_s;
  MemoryUse memory;
  /// The solve at the target as tolerance (`stcontact scaling`; compare's own runs are solves at τ already).
  std::optional<SolveAtTolerance> at_tolerance;
};

/// The report's statistics of one strategy.
struct StrategySummary {
  std::string solver;
  int repeats = 0;
  std::vector<Reach> reaches;  ///< one per targetErrors()
  double median_total_s = 0.0;
  int median_repeat = 1;       ///< the repeat drawn in the plots
};

StrategySummary summarize(const StrategyMeasurement& measurement);

/// The time ratio of `a` to `b` at target index `t` (a's median time over b's), when both reached it.
std::optional<double> timeRatio(const StrategySummary& a, const StrategySummary& b, std::size_t t);

/// The whole comparison, as the writers need it.
struct Comparison {
  std::string scene_name;
  std::string scene_file;
  std::string command;  ///< the command line that produced it
  int n_dofs = 0, n_contact_nodes = 0, n_steps = 0;
  double tolerance = 0.0;  ///< on the error estimate
  int repeats = 0;
  double reference_s = 0.0;  ///< the incremental reference and the error measure's set-up
  std::vector<StrategyMeasurement> strategies;
  RunEnvironment environment;
  std::string memory_method;
  std::string load_after;  ///< load averages when the runs ended
};

/// The summary of `solver` among `summaries`, if it was compared.
const StrategySummary* findSummary(const std::vector<StrategySummary>& summaries, const std::string& solver);

/// summarize() of every strategy, in order.
std::vector<StrategySummary> summarizeAll(const Comparison& comparison);

/// timeRatio(s, the summary of `other`, t), when `other` was compared.
std::optional<double> timeRatioTo(const std::vector<StrategySummary>& all, const StrategySummary& s,
                                  const std::string& other, std::size_t t);

}  // namespace stc
