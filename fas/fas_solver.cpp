#include "stcontact/fas/fas_solver.hpp"

#include <algorithm>
#include <string>

#include "stcontact/fas/coarse_step.hpp"
#include "stcontact/latin/indicator.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/solver/iteration_monitor.hpp"
#include "stcontact/solver/warm_start.hpp"

namespace stc::fas {
namespace {

// The fine level: relaxations from the current local-stage iterate `hat`.
class FineLevel {
 public:
  FineLevel(const Problem& problem, latin::LinearStage& global, const InterfaceHistory& start,
            IterationMonitor& monitor)
      : s(start), problem_(problem), global_(global), monitor_(monitor), solves_before_(global.sparseSolves()) {
    latin::localStage(problem.contact, s, hat);
  }

  /// One relaxation: global stage (recorded), then local stage. Returns true when the solve stops.
  bool relax(int rank) {
    global_.solve(hat, s);
    ++relaxations;
    double gap = 0.0;
    eta = latin::indicator(problem_.contact.search_direction, s, hat, &gap);
    global_.observeGap(gap);
    const bool stop = monitor_.record(relaxations, eta, s, rank, global_.sparseSolves() - solves_before_);
    latin::localStage(problem_.contact, s, hat);
    return stop;
  }

  InterfaceHistory s, hat;  ///< last global-stage and local-stage iterates
  int relaxations = 0;
  double eta = 0.0;         ///< indicator of the last relaxation

 private:
  const Problem& problem_;
  latin::LinearStage& global_;
  IterationMonitor& monitor_;
  long solves_before_;
};

// FasOptions::safeguard: the first relaxation after a coarse step judges it. A correction that
// raised the indicator more than θ = safeguard_growth times is undone (the pre-coarse local stage
// comes back; the relaxation spent on the test stays counted) and the coarse step is skipped for a
// while, doubling while it fails. A correction kept although it raised the indicator must pay back
// within its cycle: if the indicator before the next coarse step is not 1 % below the one before
// it, that next step is judged with θ = 1 (the 2-cycle of a poor coarse space, coarse step up and
// relaxation down, is broken so; docs/method.md §4).
// FasOptions::adapt_coarse_iterations: the verdicts also set i_C, halved on a rejection, one more
// on an acceptance, within [1, i_C] (FasOptions::coarse_iterations or its default for the dimension).
class CoarseGuard {
 public:
  CoarseGuard(const FasOptions& options, int dimension, bool anticipated)
      : enabled_(options.safeguard),
        adapt_(options.safeguard && options.adapt_coarse_iterations),
        max_skip_(options.max_skip),
        max_iterations_(options.coarseIterationsIn(dimension)),
        iterations_(max_iterations_),
        growth_(options.safeguard_growth.value_or(defaultSafeguardGrowth(dimension, anticipated))) {}

  /// i_C of the next coarse step.
  int coarseIterations() const { return iterations_; }
  /// Whether i_C was lowered from its most.
  bool lowered() const { return iterations_ < max_iterations_; }

  bool skipThisCycle() {
    if (skip_ == 0) return false;
    --skip_;
    return true;
  }
  void arm(const FineLevel& fine) {
    if (!enabled_) return;
    strict_ = watching_ && fine.eta > kNetProgress * eta_watched_;  // the last raise did not pay back
    watching_ = false;
    saved_ = fine.hat;
    eta_before_ = fine.eta;
    pending_ = true;
  }
  void judge(FineLevel& fine) {
    if (!pending_) return;
    pending_ = false;
    if (fine.eta <= (strict_ ? 1.0 : growth_) * eta_before_) {
      if (fine.eta > eta_before_) {
        watching_ = true;
        eta_watched_ = eta_before_;
      }
      backoff_ = 1;
      if (adapt_) iterations_ = std::min(iterations_ + 1, max_iterations_);
      return;
    }
    fine.hat = std::move(saved_);
    ++rejected;
    if (adapt_) iterations_ = std::max(iterations_ / 2, 1);
    skip_ = backoff_;
    backoff_ = std::min(2 * backoff_, max_skip_);
  }

  int rejected = 0;

 private:
  bool enabled_, adapt_;
  int max_skip_, max_iterations_, iterations_;
  bool pending_ = false;
  InterfaceHistory saved_;
  double eta_before_ = 0.0;
  int skip_ = 0, backoff_ = 1;
  double growth_;
  static constexpr double kNetProgress = 0.99;  ///< a cycle pays back when η falls by 1 %
  bool watching_ = false;     ///< the last judged correction was kept with a raised η
  double eta_watched_ = 0.0;  ///< η before that correction
  bool strict_ = false;       ///< this coarse step is judged with θ = 1
};

}  // namespace

SolveResult solveFas(const Problem& problem, latin::LinearStage& global, BasisProvider& provider,
                     const FasOptions& options, const SolveInputs& inputs, const std::string& solver_name) {
  options.validate();
  const InterfaceHistory start = startingHistory(problem, inputs);
  requireFits(start, problem);
  const EquilibriumEnergy energy(problem, global.factor());
  StoppingRule rule{options.stop};
  rule.estimate_kind = EstimateKind::CalibratedIndicator;
  rule.calibration_safety = options.estimate_safety;
  IterationMonitor monitor(solver_name, rule, &energy, inputs.reference, inputs.callback, inputs.origin);
  FineLevel fine(problem, global, start, monitor);
  CoarseGuard guard(options, problem.dimension, provider.anticipates());
  int rank = 0;
  const auto relax = [&] {
    const bool stop = fine.relax(rank);
    if (!stop) guard.judge(fine);
    return stop;
  };
  for (bool stop = false; !stop;) {
    for (int j = 0; j < options.pre_relaxations && !stop; ++j) stop = relax();
    if (stop) break;
    if (!guard.skipThisCycle()) {
      const CoarseSpace space = provider.coarseSpace(fine.hat);
      rank = space.rank();
      if (rank > 0) {
        guard.arm(fine);
        FasOptions step = options;
        step.coarse_iterations = guard.coarseIterations();
        coarseStep(problem.contact, space, step, fine.s, fine.hat);
      }
    }
    for (int j = 0; j < options.post_relaxations && !stop; ++j) stop = relax();
  }
  // The equilibrated iterate is the last global stage; its local stage is in Γ.
  InterfaceHistory admissible;
  latin::localStage(problem.contact, fine.s, admissible);
  SolveSummary summary = monitor.finish();
  if (guard.rejected > 0) {
    std::string remark = std::to_string(guard.rejected) + " coarse corrections rejected";
    if (guard.lowered())
      remark += ", i_C ended at " + std::to_string(guard.coarseIterations());
    summary.remarks.push_back(remark);
    summary.composeMessage();
  }
  return {std::move(fine.s), std::move(summary), std::move(admissible), {}, {}, {}, {}};
}

}  // namespace stc::fas
