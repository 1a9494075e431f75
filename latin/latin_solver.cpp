#include "latin/latin_solver.hpp"

#include "latin/indicator.hpp"
#include "latin/local_stage.hpp"
#include "src/solver/iteration_monitor.hpp"
#include "src/solver/warm_start.hpp"

namespace stc::latin {

SolveResult solveLatin(const Problem& problem, const LatinOptions& options, const ErrorReference* reference,
                       const IterationCallback& callback) {
  options.validate();
  GlobalStage global(problem, options.block_size);
  return solveLatin(problem, global, InterfaceHistory::zeros(problem.contact.size(), problem.numSteps()), options,
                    reference, callback);
}

SolveResult solveLatin(const Problem& problem, GlobalStage& global, const InterfaceHistory& start,
                       const LatinOptions& options, const ErrorReference* reference,
                       const IterationCallback& callback) {
  options.validate();
  requireFits(start, problem);
  IterationMonitor monitor("latin", {options.tolerance, options.max_iterations, options.stagnation_window},
                           reference, callback);
  const Eigen::VectorXd& k = problem.contact.search_direction;
  const long solves_before = global.sparseSolves();
  InterfaceHistory s = start, hat, s_new;
  for (int iteration = 1;; ++iteration) {
    localStage(problem.contact, s, hat);
    global.solve(hat, s_new);
    const double eta = indicator(k, s_new, hat);
    if (options.relaxation < 1.0) {
      s.v = options.relaxation * s_new.v + (1.0 - options.relaxation) * s.v;
      s.lambda = options.relaxation * s_new.lambda + (1.0 - options.relaxation) * s.lambda;
    } else {
      std::swap(s, s_new);
    }
    if (monitor.record(iteration, eta, s.lambda, 0, global.sparseSolves() - solves_before)) break;
  }
  return {std::move(s), monitor.finish(), std::move(hat), {}};
}

}  // namespace stc::latin
