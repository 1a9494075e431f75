#include "pgd/latin_pgd_solver.hpp"

#include <algorithm>
#include <limits>

#include "latin/indicator.hpp"
#include "latin/local_stage.hpp"
#include "pgd/separated_global_stage.hpp"
#include "src/solver/iteration_monitor.hpp"
#include "src/solver/warm_start.hpp"

namespace stc::pgd {
namespace {

// ½ ‖s + ŝ‖, the indicator's scale (docs/method.md §2).
double indicatorScale(const Eigen::VectorXd& k, const InterfaceHistory& s, const InterfaceHistory& hat) {
  return 0.5 * std::sqrt(latin::searchNormSquared(k, s.v + hat.v, s.lambda + hat.lambda));
}

// Enriches while the candidate moves s by more than γ max(η, tol); redoes the update after each mode.
// Returns the relative size of the last candidate measured (the global-stage error estimate).
double enrichWhileNeeded(SeparatedGlobalStage& stage, const Problem& problem, const LatinPgdOptions& options,
                         const InterfaceHistory& hat, InterfaceHistory& s, double& eta) {
  const Eigen::VectorXd& k = problem.contact.search_direction;
  double estimate = 0.0;
  for (int added = 0; added < options.max_modes_per_iteration && stage.modes().rank() < options.max_rank; ++added) {
    const RankOnePair pair = stage.candidate(options.enrichment);
    const double scale = indicatorScale(k, s, hat);
    // From s = ŝ = 0 (the first iteration of an unloaded start) any mode is a 100% change.
    estimate = scale > 0.0 ? stage.interfaceNorm(pair) / scale : (pair.space.size() > 0 ? 1.0 : 0.0);
    if (!(estimate > options.enrichment_ratio * std::max(eta, options.tolerance)) || !stage.add(pair)) break;
    stage.update(hat, s);
    eta = latin::indicator(k, s, hat);
  }
  return estimate;
}

}  // namespace

SolveResult solveLatinPgd(const Problem& problem, const LatinPgdOptions& options, const ErrorReference* reference,
                          const IterationCallback& callback) {
  options.validate();
  const latin::GlobalStage global(problem);
  return solveLatinPgd(problem, global, options, reference, callback);
}

SolveResult solveLatinPgd(const Problem& problem, const latin::GlobalStage& global, const LatinPgdOptions& options,
                          const ErrorReference* reference, const IterationCallback& callback) {
  return solveLatinPgd(problem, global, InterfaceHistory::zeros(problem.contact.size(), problem.numSteps()),
                       Eigen::MatrixXd(problem.numFreeDofs(), 0), options, reference, callback);
}

SolveResult solveLatinPgd(const Problem& problem, const latin::GlobalStage& global, const InterfaceHistory& start,
                          const Eigen::MatrixXd& seed_modes, const LatinPgdOptions& options,
                          const ErrorReference* reference, const IterationCallback& callback) {
  options.validate();
  requireFits(start, problem);
  IterationMonitor monitor("latin-pgd", {options.tolerance, options.max_iterations, options.stagnation_window},
                           reference, callback);
  SeparatedGlobalStage stage(problem, global);
  stage.seed(seed_modes, options.max_rank);
  InterfaceHistory s = start, hat;
  double previous_eta = std::numeric_limits<double>::infinity(), last_estimate = 0.0;
  for (int iteration = 1;; ++iteration) {
    latin::localStage(problem.contact, s, hat);
    stage.update(hat, s);
    double eta = latin::indicator(problem.contact.search_direction, s, hat);
    const bool check = iteration == 1 || stage.modes().rank() == 0 || eta > options.stagnation_ratio * previous_eta ||
                       eta <= options.tolerance || eta < last_estimate;
    double recorded = eta;
    if (check) {
      last_estimate = enrichWhileNeeded(stage, problem, options, hat, s, eta);
      recorded = std::max(eta, last_estimate);
    }
    previous_eta = eta;
    if (monitor.record(iteration, recorded, s.lambda, stage.modes().rank(), stage.sparseSolves())) break;
  }
  InterfaceHistory admissible;
  latin::localStage(problem.contact, s, admissible);
  return {std::move(s), monitor.finish(), std::move(admissible), stage.modes().modes()};
}

}  // namespace stc::pgd
