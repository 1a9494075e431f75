#pragma once
// Shared bookkeeping of the iterative solvers: records each iteration (indicator, error estimate,
// true error when a reference is known, rank, sparse solves, wall time), and decides when to stop:
// converged (the error estimate of src/solver/error_estimate.hpp at most the tolerance, or the
// iterate certified as the solution without contact, src/solver/contact_free_certificate.hpp),
// iteration limit, stagnation, NaN/Inf (numerical issue) or the user's callback.
#include <Eigen/Core>
#include <chrono>
#include <optional>
#include <string>

#include "stcontact/options/stopping_options.hpp"
#include "stcontact/solver/calibrated_estimate.hpp"
#include "stcontact/solver/equilibrium_energy.hpp"
#include "stcontact/solver/error_estimate.hpp"
#include "stcontact/solver/error_measure.hpp"
#include "stcontact/solver/record_origin.hpp"
#include "stcontact/solver/solve_summary.hpp"

namespace stc {

/// Which estimate of the true error a solver stops on (docs/method.md §2).
enum class EstimateKind {
  Extrapolation,        ///< ErrorEstimator: MPE of the iterates one period apart (LATIN)
  CalibratedIndicator,  ///< CalibratedIndicatorEstimator: the indicator scaled by earlier iterates (FAS)
};

/// The strategy's stopping options and the estimate it stops on. The estimator's own constants are
/// set by the strategy that knows its iteration (FAS: the calibrated indicator and its safety).
struct StoppingRule {
  StoppingOptions stop;         ///< tolerance on the estimate, iteration cap, stagnation window
  int estimate_period = 1;      ///< iterations per period of the iteration (ErrorEstimator)
  int estimate_order = 2;       ///< order of its extrapolation (ErrorEstimator)
  double estimate_safety = 2.0; ///< its safety factor (ErrorEstimator)
  int estimate_window = 1;      ///< periods of its largest ratio (ErrorEstimator)
  double estimate_min_rate = 0.1;  ///< the smallest contraction per period it assumes
  EstimateKind estimate_kind = EstimateKind::Extrapolation;
  double calibration_safety = 2.5;  ///< s of CalibratedIndicatorEstimator
  /// Extrapolation: records after a change of the stage's rank within which an estimate below the
  /// tolerance needs the previous record's below it too (the order-2 extrapolation's differences
  /// span its last 3 records; IterationMonitor::confirmed).
  int confirm_window = 3;
};

/// The reason of a converged solve whose last record is `last` ("error estimate E <= tolerance T after
/// N iterations (indicator I)").
std::string convergedReason(const IterationRecord& last, double tolerance);
/// The reason of a solve stopped by its iteration cap `max_iterations`, its last indicator `indicator`.
std::string iterationLimitReason(int max_iterations, double indicator);

class IterationMonitor {
 public:
  /// `energy` normalises the error estimate; without it (unit tests of the bookkeeping) the
  /// indicator stands in for the estimate. The records stored and handed to `callback` count from
  /// `origin` (record_origin.hpp); the stopping decisions, and the summary's iterations and
  /// relaxations, are this solve's own.
  IterationMonitor(std::string solver, StoppingRule rule, const EquilibriumEnergy* energy,
                   const ErrorMeasure* reference = nullptr, IterationCallback callback = {}, RecordOrigin origin = {});

  /// Records one iteration whose equilibrated iterate is `s`; returns true when the solve must stop
  /// (the summary says why).
  bool record(int relaxations, double indicator, const InterfaceHistory& s, int rank, long sparse_solves);

  /// Final summary (termination, message, totals); call once at the end.
  SolveSummary finish();
  /// Seconds on the origin's clock (since construction without one), the true-error measures' time
  /// excluded.
  double elapsed() const;

 private:
  bool stop(Termination termination, std::string reason);
  double estimate(const InterfaceHistory& s, double indicator, double energy);  ///< by rule_.estimate_kind
  std::optional<double> measureError(const Eigen::MatrixXd& lambda);  // and adds its time to measure_s_
  bool confirmed(const IterationRecord& r) const;  // an estimate below the tolerance stands (a map change)


  SolveSummary summary_;
  StoppingRule rule_;
  const EquilibriumEnergy* energy_;
  ErrorEstimator estimator_;
  CalibratedIndicatorEstimator calibrated_;
  const ErrorMeasure* reference_;
  IterationCallback callback_;
  RecordOrigin origin_;
  std::chrono::steady_clock::time_point start_;
  double measure_s_ = 0.0;  // seconds spent in the true-error measure
  double best_indicator_ = 0.0;
  int best_iteration_ = 0;
  int rank_changed_ = 0;  ///< the last record whose rank differs from the one before (0: none)

};

}  // namespace stc
