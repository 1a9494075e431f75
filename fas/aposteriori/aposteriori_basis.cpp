#include "stcontact/fas/aposteriori/aposteriori_basis.hpp"

#include <algorithm>

#include "stcontact/operators/displacement.hpp"
#include "stcontact/pgd/space_time_svd.hpp"

namespace stc::fas {

Eigen::MatrixXd aposterioriModes(const Problem& problem, const SpdSolver& stiffness_free,
                                 const Eigen::MatrixXd& converged_lambda, int count) {
  const Eigen::MatrixXd U = fullDisplacements(problem, stiffness_free, converged_lambda);
  const pgd::SpaceTimeSvd svd = pgd::energySvd(U, problem.stiffness);
  const int kept = std::min(count, svd.resolved);
  Eigen::MatrixXd modes(problem.numFreeDofs(), kept);
  for (int i = 0; i < problem.numFreeDofs(); ++i) modes.row(i) = svd.space.row(problem.free_dofs[i]).head(kept);
  return modes;
}

}  // namespace stc::fas
