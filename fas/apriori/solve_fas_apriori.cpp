#include "stcontact/fas/apriori/solve_fas_apriori.hpp"

#include "stcontact/fas/apriori/reduced_interface.hpp"

namespace stc::fas {

SolveResult solveFasApriori(const Problem& problem, const FasAprioriOptions& options, const SolveInputs& inputs) {
  return solveOnSeparatedFineLevel(problem, options, inputs, {});
}

SolveResult solveOnSeparatedFineLevel(const Problem& problem, const FasAprioriOptions& options,
                                      const SolveInputs& inputs, const SeparatedCoarseBasis& coarse_basis) {
  options.validate();
  if (options.zone.enabled && problem.contact.size() > 0)
    return solveAprioriOnContactZone(problem, options, inputs, coarse_basis);
  FasAprioriOptions own = options;
  if (inputs.start) own.nested.instants = 0;  // nested iteration in time begins from scratch
  Eigen::MatrixXd none;
  return solveAprioriOn(problem, own, inputs, Eigen::SparseMatrix<double>(0, problem.numFreeDofs()), none,
                        coarse_basis);
}

}  // namespace stc::fas
