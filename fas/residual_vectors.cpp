#include "stcontact/fas/residual_vectors.hpp"

#include <algorithm>

#include "stcontact/linalg/dense_decompositions.hpp"

namespace stc::fas {

Eigen::MatrixXd residualVectors(const Eigen::MatrixXd& u_tilde, const Eigen::MatrixXd& fixed,
                                const Eigen::SparseMatrix<double>& A, int count) {
  if (count <= 0) return Eigen::MatrixXd(u_tilde.rows(), 0);
  Eigen::MatrixXd R = u_tilde;
  if (fixed.cols() > 0) R.noalias() -= fixed * (fixed.transpose() * (A * u_tilde));
  return rangeOf(R, count);
}

Eigen::MatrixXd rangeOf(const Eigen::MatrixXd& R, int count) {
  if (count <= 0 || R.cols() == 0) return Eigen::MatrixXd(R.rows(), 0);
  // Randomized range finder (Halko, Martinsson, Tropp 2011, alg. 4.1) with 5 extra samples.
  const int samples = std::min<int>(count + 5, static_cast<int>(R.cols()));
  const Eigen::MatrixXd Q = linalg::randomizedRange(R, samples, 0, 20130513u);
  const linalg::Svd svd = linalg::singularValueDecomposition(Q.transpose() * R, linalg::SvdMethod::qr_iteration, linalg::kThinU);
  const Eigen::VectorXd& sigma = svd.values;
  int keep = 0;
  while (keep < std::min<int>(count, static_cast<int>(sigma.size())) && sigma[keep] > 1e-12 * sigma[0]) ++keep;
  return Q * svd.U.leftCols(keep);
}

}  // namespace stc::fas
