#include "stcontact/fas/apriori/solve_fas_apriori.hpp"

#include "stcontact/fas/apriori/reduced_interface.hpp"

namespace stc::fas {

SolveResult solveFasApriori(const Problem& problem, const FasAprioriOptions& options, const SolveInputs& inputs) {
  options.validate();
  if (options.zone.enabled && problem.contact.size() > 0) return solveAprioriOnContactZone(problem, options, inputs);
  FasAprioriOptions own = options;
  if (inputs.start) own.nested.instants = 0;  // nested iteration in time begins from scratch
  Eigen::MatrixXd none;
  return solveAprioriOn(problem, own, inputs, Eigen::SparseMatrix<double>(0, problem.numFreeDofs()), none);
}

}  // namespace stc::fas
