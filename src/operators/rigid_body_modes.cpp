#include "stcontact/operators/rigid_body_modes.hpp"

#include <Eigen/QR>

namespace stc {

Eigen::MatrixXd rigidBodyModesOfFreeDofs(const Problem& problem) {
  const int d = problem.dimension;
  const Eigen::MatrixXd x = problem.nodePositions();  // d × nodes
  const Eigen::VectorXd centre = x.rowwise().mean();
  const int modes = d == 2 ? 3 : 6;
  Eigen::MatrixXd R(problem.numFreeDofs(), modes);
  for (int i = 0; i < problem.numFreeDofs(); ++i) {
    const int dof = problem.free_dofs[static_cast<std::size_t>(i)];
    const int node = dof / d, c = dof % d;
    const Eigen::VectorXd r = x.col(node) - centre;
    R.row(i).setZero();
    R(i, c) = 1.0;  // translation along c
    if (d == 2) {
      R(i, 2) = c == 0 ? -r(1) : r(0);  // rotation: (−y, x)
    } else {
      // rotation about axis k: (e_k × r)_c = ε_{c k l} r_l
      const int k1 = (c + 1) % 3, k2 = (c + 2) % 3;
      R(i, 3 + k1) = r(k2);   // ε_{c k1 k2} = +1
      R(i, 3 + k2) = -r(k1);  // ε_{c k2 k1} = −1
    }
  }
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(R);
  return qr.householderQ() * Eigen::MatrixXd::Identity(R.rows(), modes);
}

}  // namespace stc
