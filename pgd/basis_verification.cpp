#include "stcontact/pgd/basis_verification.hpp"

#include <cmath>

#include "stcontact/linalg/dense_decompositions.hpp"

namespace stc::pgd {

Eigen::VectorXd principalCosines(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Y,
                                 const Eigen::SparseMatrix<double>& M) {
  const Eigen::MatrixXd Qx = linalg::orthonormalIn(X, M), Qy = linalg::orthonormalIn(Y, M);
  if (Qx.cols() == 0 || Qy.cols() == 0) return {};
  const Eigen::MatrixXd C = Qx.transpose() * (M * Qy);
  return linalg::singularValueDecomposition(C, linalg::SvdMethod::jacobi, linalg::kValuesOnly).values.cwiseMin(1.0);
}

double projectionError(const Eigen::MatrixXd& U, const Eigen::MatrixXd& Y, const Eigen::SparseMatrix<double>& M) {
  const Eigen::MatrixXd MU = M * U;
  const double total = U.cwiseProduct(MU).sum();
  if (!(total > 0.0)) return 0.0;
  const Eigen::MatrixXd Q = linalg::orthonormalIn(Y, M);
  const Eigen::MatrixXd c = Q.transpose() * MU;  // ‖U − QQᵀMU‖²_M = ‖U‖²_M − ‖c‖²
  return std::sqrt(std::max(0.0, total - c.squaredNorm()) / total);
}

}  // namespace stc::pgd
