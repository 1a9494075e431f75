#pragma once
// The runs of `stcontact compare`: the incremental reference, then each strategy's error run and
// timed repeats through fas::solveByName, with the peak memory of the strategy's runs.
#include <memory>
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
};

/// Solves `problem` with the incremental solver and builds the true-error measure on it.
ReferenceSolution computeReference(const Problem& problem, bool quiet);

struct CompareContext {
  const Problem& problem;
  const SolverSpec& spec;
  const ReferenceSolution& reference;
  int repeats = 3;
  bool quiet = false;
};

/// One error run (iterative strategies only), then `repeats` timed runs; see docs/compare.md.
StrategyMeasurement measureStrategy(const std::string& solver, const CompareContext& context);

}  // namespace stc::cli
