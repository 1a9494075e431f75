#include "stcontact/operators/displacement.hpp"

namespace stc {

Eigen::MatrixXd freeDisplacements(const Problem& problem, const SpdSolver& stiffness_free, const Eigen::MatrixXd& lambda) {
  Eigen::MatrixXd rhs = problem.loadBlock(0, problem.numSteps());
  rhs.noalias() += problem.contact.B.transpose() * lambda;
  return stiffness_free.solveOnThreads(rhs);
}

Eigen::MatrixXd fullDisplacements(const Problem& problem, const SpdSolver& stiffness_free, const Eigen::MatrixXd& lambda) {
  const Eigen::MatrixXd u_free = freeDisplacements(problem, stiffness_free, lambda);
  Eigen::MatrixXd U(problem.numDofs(), problem.numSteps());
  for (int k = 0; k < problem.numSteps(); ++k) U.col(k) = problem.fullDisplacement(u_free.col(k), k);
  return U;
}

Eigen::VectorXd freeDisplacementAt(const Problem& problem, const SpdSolver& stiffness_free,
                                   const Eigen::VectorXd& lambda_k, int k, SpdSolver::Workspace& workspace) {
  const Eigen::MatrixXd rhs = problem.load(k) + problem.contact.B.transpose() * lambda_k;
  return stiffness_free.solve(rhs, workspace);
}

}  // namespace stc
