#include "fas/residual_vectors.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <random>

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
  std::mt19937 rng(20130513);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd omega(R.cols(), samples);
  for (Eigen::Index j = 0; j < omega.size(); ++j) omega(j) = normal(rng);
  const Eigen::MatrixXd Z = R * omega;
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Z);
  const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(R.rows(), samples);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Q.transpose() * R, Eigen::ComputeThinU);
  const Eigen::VectorXd& sigma = svd.singularValues();
  int keep = 0;
  while (keep < std::min<int>(count, static_cast<int>(sigma.size())) && sigma[keep] > 1e-12 * sigma[0]) ++keep;
  return Q * svd.matrixU().leftCols(keep);
}

}  // namespace stc::fas
