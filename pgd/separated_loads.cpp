#include "stcontact/pgd/separated_loads.hpp"

namespace stc::pgd {

SeparatedLoads separatedLoads(const Problem& problem) {
  const int q = static_cast<int>(problem.loads.size());
  SeparatedLoads out{Eigen::MatrixXd(problem.numFreeDofs(), q), Eigen::MatrixXd(q, problem.numSteps())};
  for (int i = 0; i < q; ++i) {
    out.F.col(i) = problem.loads[i].free_force;
    out.G.row(i) = Eigen::Map<const Eigen::RowVectorXd>(problem.loads[i].values.data(), problem.numSteps());
  }
  return out;
}

}  // namespace stc::pgd
