#include "pgd/basis_verification.hpp"

#include <cmath>

#include "src/linalg/dense_decompositions.hpp"

namespace stc::pgd {

Eigen::MatrixXd orthonormalIn(const Eigen::MatrixXd& V, const Eigen::SparseMatrix<double>& M) {
  if (V.cols() == 0) return V;
  Eigen::MatrixXd G = V.transpose() * (M * V);
  G = 0.5 * (G + G.transpose()).eval();
  const linalg::SymmetricEigen eig = linalg::symmetricEigen(G);
  const Eigen::VectorXd& d = eig.values;
  int keep = 0;
  for (Eigen::Index j = 0; j < d.size(); ++j) keep += d[j] > 1e-12 * d.maxCoeff();
  return V * eig.vectors.rightCols(keep) * d.tail(keep).cwiseSqrt().cwiseInverse().asDiagonal();
}

Eigen::VectorXd principalCosines(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Y,
                                 const Eigen::SparseMatrix<double>& M) {
  const Eigen::MatrixXd Qx = orthonormalIn(X, M), Qy = orthonormalIn(Y, M);
  if (Qx.cols() == 0 || Qy.cols() == 0) return {};
  const Eigen::MatrixXd C = Qx.transpose() * (M * Qy);
  return linalg::singularValueDecomposition(C, linalg::SvdMethod::jacobi, linalg::kValuesOnly).values.cwiseMin(1.0);
}

double projectionError(const Eigen::MatrixXd& U, const Eigen::MatrixXd& Y, const Eigen::SparseMatrix<double>& M) {
  const Eigen::MatrixXd MU = M * U;
  const double total = U.cwiseProduct(MU).sum();
  if (!(total > 0.0)) return 0.0;
  const Eigen::MatrixXd Q = orthonormalIn(Y, M);
  const Eigen::MatrixXd c = Q.transpose() * MU;  // ‖U − QQᵀMU‖²_M = ‖U‖²_M − ‖c‖²
  return std::sqrt(std::max(0.0, total - c.squaredNorm()) / total);
}

}  // namespace stc::pgd
