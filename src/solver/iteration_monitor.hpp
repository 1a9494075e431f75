#pragma once
// Shared bookkeeping of the iterative solvers: records each iteration (indicator, true error when a
// reference is known, rank, sparse solves, wall time), and decides when to stop: converged,
// iteration limit, stagnation, NaN/Inf (numerical issue) or the user's callback.
#include <Eigen/Core>
#include <chrono>
#include <string>

#include "src/core/solver_settings.hpp"
#include "src/solver/error_reference.hpp"
#include "src/solver/solve_summary.hpp"

namespace stc {

struct StoppingRule {
  double tolerance = defaults::tolerance;      ///< on the indicator
  int max_iterations = defaults::max_iterations;
  int stagnation_window = 0;    ///< iterations without a 1% decrease of the best indicator (0: off)
};

class IterationMonitor {
 public:
  IterationMonitor(std::string solver, StoppingRule rule, const ErrorReference* reference = nullptr,
                   IterationCallback callback = {});

  /// Records one iteration; returns true when the solve must stop (the summary says why).
  bool record(int relaxations, double indicator, const Eigen::MatrixXd& lambda, int rank, long sparse_solves);
  /// Final summary (termination, message, totals); call once at the end.
  SolveSummary finish();
  double elapsed() const;

 private:
  bool stop(Termination termination, std::string message);

  SolveSummary summary_;
  StoppingRule rule_;
  const ErrorReference* reference_;
  IterationCallback callback_;
  std::chrono::steady_clock::time_point start_;
  double best_indicator_ = 0.0;
  int best_iteration_ = 0;
};

}  // namespace stc
