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
/// An indicator η at most this (64 ε) says the iterate is LATIN's fixed point to rounding: the
/// global stage of its local stage returns it, so it lies in both A_d and Γ and is the solution
/// (docs/method.md §2). Such a solve is converged, for a tolerance of at least kFixedPointError,
/// whatever its estimate can tell: a solution that stores no strain energy (nothing moves, a body
/// lifted rigidly) has no relative error to estimate, and its estimate is +∞ or rounding noise.
inline constexpr double kFixedPointIndicator = 64.0 * 2.220446049250313e-16;
/// The true error such a fixed point is certified to: rounding (1e-14 measured on the seed scene),
/// held to 1e-12, the estimate's own round-off floor (src/solver/error_estimate.cpp). A tolerance
/// below it is not met by a fixed point to rounding (the solve runs on, honestly, to its cap).
inline constexpr double kFixedPointError = 1e-12;

/// The reason of a solve stopped at a fixed point (kFixedPointIndicator).
std::string fixedPointReason(const IterationRecord& last);
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
  /// (the summary says why). `unrelaxed_step`: the energy norm of the unrelaxed map's step, when the
  /// iteration relaxes it (ErrorEstimator::record). `stage_error`: a bound, in energy, on the
  /// distance of `s` from the iterate an exact global stage would have given (a controlled stage's
  /// ½ ‖r‖_{k⁻¹}), which the extrapolation of the iterates cannot see (ErrorEstimator::record).
  bool record(int relaxations, double indicator, const InterfaceHistory& s, int rank, long sparse_solves,
              std::optional<double> unrelaxed_step = std::nullopt, double stage_error = 0.0);

  /// Final summary (termination, message, totals); call once at the end.
  SolveSummary finish();
  /// Seconds on the origin's clock (since construction without one), the true-error measures' time
  /// excluded.
  double elapsed() const;

 private:
  bool stop(Termination termination, std::string reason);
  /// by rule_.estimate_kind
  double estimate(const InterfaceHistory& s, double indicator, double energy, std::optional<double> unrelaxed_step,
                  double stage_error);
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
