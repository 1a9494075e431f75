#include "stcontact/pgd/displacement_history.hpp"

#include "stcontact/incremental/condensed_interface.hpp"

namespace stc::pgd {

Eigen::MatrixXd fullDisplacementHistory(const Problem& problem, const SpdFactor& stiffness_free,
                                        const Eigen::MatrixXd& lambda) {
  const Eigen::MatrixXd u_free = displacementsFromForces(problem, stiffness_free, lambda);
  Eigen::MatrixXd U(problem.numDofs(), problem.numSteps());
  for (int k = 0; k < problem.numSteps(); ++k) U.col(k) = problem.fullDisplacement(u_free.col(k), k);
  return U;
}

}  // namespace stc::pgd
