#pragma once
// The runs of `stcontact compare`: the incremental reference, then each strategy's error run and
// timed repeats through solveByName, with the peak memory of the strategy's runs.
#include <memory>
#include <optional>
#include <string>

#include "src/problem/problem.hpp"
#include "src/report/comparison.hpp"
#include "src/scene/scene.hpp"
#include "src/solver/error_reference.hpp"

namespace stc::cli {

struct ReferenceSolution {
  std::unique_ptr<ErrorReference> reference;
  double solve_s = 0.0;  ///< the incremental solve alone
  double total_s = 0.0;  ///< with the error measure's set-up (factor of K_ff, Delassus operator)
  double factor_nonzeros = 0.0;  ///< entries of the Cholesky factor of K_ff (SpdFactor::factorNonZeros)
};

/// Solves `problem` with the incremental solver and builds the true-error measure on it.
ReferenceSolution computeReference(const Problem& problem, bool quiet);

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
  bool quiet = false;
  EarlyStop stop = {};
  /// Called after every record of every run (error and timed); false stops that run, like a
  /// solver's callback (the Python module's Ctrl-C and per-iteration callback). None by default.
  IterationCallback keep_going = {};
};

/// One error run (iterative strategies only), then `repeats` timed runs; see docs/compare.md. With
/// an EarlyStop, the message says where and why the error run was stopped.
StrategyMeasurement measureStrategy(const std::string& solver, const CompareContext& context);

}  // namespace stc::cli
