#include "stcontact/fas/apriori/solve_fas_apriori.hpp"

#include "stcontact/fas/apriori/reduced_interface.hpp"
#include "stcontact/fas/apriori/single_solve.hpp"

namespace stc::fas {

SolveResult solveFasApriori(const Problem& problem, const FasAprioriOptions& options, const SolveInputs& inputs) {
  return solveOnSeparatedFineLevel(problem, options, inputs, {});
}

SolveResult solveOnSeparatedFineLevel(const Problem& problem, const FasAprioriOptions& options,
                                      const SolveInputs& inputs, const SeparatedCoarseBasis& coarse_basis) {
  options.validate();
  std::unique_ptr<PreparedOperators> own_operators;
  SolveInputs shared = inputs;  // one owner of the operators, and the solve's clock, for every part
  shared.operators = &operatorsOr(inputs.operators, own_operators);
  shared.origin = inputs.origin.clocked();
  if (options.zone.enabled && problem.contact.size() > 0)
    return solveAprioriOnContactZone(problem, options, shared, coarse_basis);
  FasAprioriOptions own = options;
  if (inputs.start) own.nested.instants = 0;  // nested iteration in time begins from scratch
  Eigen::MatrixXd none;
  return solveAprioriOn(problem, own, shared, Eigen::SparseMatrix<double>(0, problem.numFreeDofs()), none,
                        coarse_basis);
}

}  // namespace stc::fas
