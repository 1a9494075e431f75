#include "stcontact/solver/iteration_monitor.hpp"

#include <cmath>
#include <sstream>

#include "stcontact/core/clock.hpp"
#include "stcontact/solver/contact_free_certificate.hpp"

namespace stc {

std::string convergedReason(const IterationRecord& last, double tolerance) {
  std::ostringstream reason;
  reason << "error estimate " << last.error_estimate << " <= tolerance " << tolerance << " after " << last.iteration
         << " iterations (indicator " << last.indicator << ")";
  return reason.str();
}

std::string fixedPointReason(const IterationRecord& last) {
  std::ostringstream reason;
  reason << "a fixed point after " << last.iteration << " iterations: indicator " << last.indicator
         << " (the global stage returns the local stage's iterate to rounding, which is the solution)";
  return reason.str();
}

std::string iterationLimitReason(int max_iterations, double indicator) {
  std::ostringstream reason;
  reason << "iteration limit " << max_iterations << " reached with indicator " << indicator;
  return reason.str();
}

IterationMonitor::IterationMonitor(std::string solver, StoppingRule rule, const EquilibriumEnergy* energy,
                                   const ErrorMeasure* reference, IterationCallback callback, RecordOrigin origin)
    : rule_(rule),
      energy_(energy),
      estimator_(rule.estimate_period, rule.estimate_order, rule.estimate_safety, rule.estimate_window,
                 rule.estimate_min_rate),
      calibrated_(rule.calibration_safety),
      reference_(reference),
      callback_(std::move(callback)),
      origin_(origin),
      start_(origin.clock.value_or(std::chrono::steady_clock::now())) {
  summary_.solver = std::move(solver);
}

// The solver's clock: time since the start, less the time spent measuring the true error (an
// observation of the run, not part of the solver's work: an error run and a run without the
// reference then tell the same time).
double IterationMonitor::elapsed() const {
  return secondsSince(start_) - measure_s_ + origin_.wall_s;
}

std::optional<double> IterationMonitor::measureError(const Eigen::MatrixXd& lambda) {
  if (!reference_ || !reference_->defined()) return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  const double error = reference_->relativeError(lambda);
  measure_s_ += secondsSince(start);
  return error;
}

bool IterationMonitor::record(int relaxations, double indicator, const InterfaceHistory& s, int rank,
                              long sparse_solves, std::optional<double> unrelaxed_step, double stage_error) {
  const Eigen::MatrixXd& lambda = s.lambda;
  IterationRecord r;
  r.iteration = static_cast<int>(summary_.history.size()) + 1;
  r.relaxations = relaxations;
  r.indicator = indicator;
  if (!summary_.history.empty() && rank != summary_.history.back().rank) rank_changed_ = r.iteration;
  const std::optional<double> energy = energy_ ? std::optional<double>((*energy_)(s)) : std::nullopt;
  r.error_estimate = energy ? estimate(s, indicator, *energy, unrelaxed_step, stage_error) : indicator;
  r.energy = energy;
  r.error = measureError(lambda);
  r.rank = rank;
  r.sparse_solves = static_cast<int>(sparse_solves);
  r.wall_s = elapsed();
  summary_.history.push_back(origin_.applied(r));
  if (!std::isfinite(indicator) || !lambda.allFinite())
    return stop(Termination::NumericalIssue, "NaN or Inf in the iterate at iteration " + std::to_string(r.iteration));
  if (energy)
    if (auto reason = contactFreeSolution(energy_->problem().contact, s, *energy, rule_.stop.tolerance))
      return stop(Termination::Converged, *reason);
  if (indicator <= kFixedPointIndicator && rule_.stop.tolerance >= kFixedPointError)
    return stop(Termination::Converged, fixedPointReason(r));
  if (r.error_estimate <= rule_.stop.tolerance && confirmed(r))
    return stop(Termination::Converged, convergedReason(r, rule_.stop.tolerance));
  if (r.iteration == 1 || indicator < 0.99 * best_indicator_) {
    best_indicator_ = indicator;
    best_iteration_ = r.iteration;
  } else if (rule_.stop.stagnation_window > 0 && r.iteration - best_iteration_ >= rule_.stop.stagnation_window) {
    std::ostringstream msg;
    msg << "stagnated: indicator has not decreased by 1% in " << rule_.stop.stagnation_window << " iterations (best "
        << best_indicator_ << ")";
    return stop(Termination::Stagnated, msg.str());
  }
  if (callback_ && !callback_(origin_.applied(r))) return stop(Termination::StoppedByCallback, "stopped by the callback");
  if (r.iteration >= rule_.stop.max_iterations)
    return stop(Termination::MaxIterations, iterationLimitReason(rule_.stop.max_iterations, indicator));
  return false;
}

// The extrapolation assumes one map. A global stage whose rank changed (latin-pgd's separated stage
// adding directions) iterates another from then on, and an estimate from differences that straddle
// the change can dip below the tolerance for one record: 8.4e-7 between records at 3.2e-6, true
// error 1.7e-6 (3D, κ = 0.1, tests/strategies/test_stopping_scan.cpp). Within rule_.confirm_window
// records of a change, the previous record must have been below the tolerance too.
bool IterationMonitor::confirmed(const IterationRecord& r) const {
  if (rule_.estimate_kind != EstimateKind::Extrapolation || rank_changed_ == 0) return true;
  if (r.iteration - rank_changed_ > rule_.confirm_window) return true;
  const std::vector<IterationRecord>& h = summary_.history;
  return h.size() >= 2 && h[h.size() - 2].error_estimate <= rule_.stop.tolerance;
}

// The estimate of the relative error; +∞ when the iterate stores no strain energy (a rigid motion:
// the relative error is 0/0 and the estimate rounding noise; contact_free_certificate.hpp).
double IterationMonitor::estimate(const InterfaceHistory& s, double indicator, double energy,
                                  std::optional<double> unrelaxed_step, double stage_error) {
  const double estimate = rule_.estimate_kind == EstimateKind::CalibratedIndicator
                              ? calibrated_.record(s, indicator, energy)
                              : estimator_.record(s, energy, unrelaxed_step, stage_error);
  return storesNoStrainEnergy(energy_->problem().contact, s, energy) ? INFINITY : estimate;
}

bool IterationMonitor::stop(Termination termination, std::string reason) {
  summary_.termination = termination;
  summary_.reason = std::move(reason);
  return true;
}

SolveSummary IterationMonitor::finish() {
  summary_.iterations = static_cast<int>(summary_.history.size());
  if (!summary_.history.empty()) {
    const auto& last = summary_.history.back();
    summary_.relaxations = last.relaxations - origin_.relaxations;
    summary_.indicator = last.indicator;
    summary_.error_estimate = last.error_estimate;
    summary_.error = last.error;
  }
  summary_.wall_s = elapsed();
  summary_.composeMessage();
  return summary_;
}

}  // namespace stc
