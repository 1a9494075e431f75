#include "fas/fas_solver.hpp"

#include "fas/coarse_step.hpp"
#include "latin/indicator.hpp"
#include "latin/local_stage.hpp"
#include "src/solver/iteration_monitor.hpp"

namespace stc::fas {
namespace {

// The fine level: relaxations from the current local-stage iterate `hat`.
class FineLevel {
 public:
  FineLevel(const Problem& problem, latin::GlobalStage& global, IterationMonitor& monitor)
      : problem_(problem), global_(global), monitor_(monitor), solves_before_(global.sparseSolves()) {
    s = InterfaceHistory::zeros(problem.contact.size(), problem.numSteps());
    latin::localStage(problem.contact, s, hat);
  }

  /// One relaxation: global stage (recorded), then local stage. Returns true when the solve stops.
  bool relax(int rank) {
    global_.solve(hat, s, &u);
    ++relaxations;
    const double eta = latin::indicator(problem_.contact.search_direction, s, hat);
    const bool stop = monitor_.record(relaxations, eta, s.lambda, rank, global_.sparseSolves() - solves_before_);
    latin::localStage(problem_.contact, s, hat);
    return stop;
  }

  InterfaceHistory s, hat;  ///< last global-stage and local-stage iterates
  Eigen::MatrixXd u;        ///< free displacements of the last global stage
  int relaxations = 0;

 private:
  const Problem& problem_;
  latin::GlobalStage& global_;
  IterationMonitor& monitor_;
  long solves_before_;
};

}  // namespace

SolveResult solveFas(const Problem& problem, latin::GlobalStage& global, BasisProvider& provider,
                     const FasOptions& options, const std::string& solver_name, const ErrorReference* reference,
                     const IterationCallback& callback) {
  options.validate();
  IterationMonitor monitor(solver_name, {options.tolerance, options.max_relaxations, options.stagnation_window},
                           reference, callback);
  FineLevel fine(problem, global, monitor);
  int rank = 0;
  Eigen::MatrixXd xi;
  for (bool stop = false; !stop;) {
    for (int j = 0; j < options.pre_relaxations && !stop; ++j) stop = fine.relax(rank);
    if (stop) break;
    const CoarseSpace space = provider.coarseSpace(fine.u, fine.s);
    rank = space.rank();
    if (rank > 0) coarseStep(problem.contact, space, options, fine.s, fine.hat, xi);
    for (int j = 0; j < options.post_relaxations && !stop; ++j) stop = fine.relax(rank);
  }
  // The equilibrated iterate is the last global stage; its local stage is in Γ.
  InterfaceHistory admissible;
  latin::localStage(problem.contact, fine.s, admissible);
  return {std::move(fine.s), monitor.finish(), std::move(admissible)};
}

}  // namespace stc::fas
