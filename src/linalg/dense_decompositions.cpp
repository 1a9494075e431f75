#include "stcontact/linalg/dense_decompositions.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <random>

namespace stc::linalg {
namespace {

template <class Decomposition>
Svd fromDecomposition(const Decomposition& d, unsigned vectors) {
  Svd svd;
  svd.values = d.singularValues();
  if (vectors & kThinU) svd.U = d.matrixU();
  if (vectors & kThinV) svd.V = d.matrixV();
  return svd;
}

}  // namespace

Eigen::MatrixXd orthonormalColumns(const Eigen::MatrixXd& Y) {
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Y);
  return qr.householderQ() * Eigen::MatrixXd::Identity(Y.rows(), Y.cols());
}

SymmetricEigen symmetricEigen(const Eigen::MatrixXd& M) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(M);
  SymmetricEigen result;
  result.converged = eig.info() == Eigen::Success;
  result.values = eig.eigenvalues();
  result.vectors = eig.eigenvectors();
  return result;
}

Eigen::MatrixXd orthonormalIn(const Eigen::MatrixXd& V, const Eigen::SparseMatrix<double>& M, double drop) {
  if (V.cols() == 0) return V;
  const Eigen::MatrixXd MV = M * V;
  Eigen::MatrixXd G = V.transpose() * MV;
  G = 0.5 * (G + G.transpose()).eval();  // symmetric to the last bit before the eigensolver
  const SymmetricEigen eig = symmetricEigen(G);
  const Eigen::VectorXd& d = eig.values;  // ascending
  const double largest = d.maxCoeff();
  int keep = 0;
  for (Eigen::Index j = 0; j < d.size(); ++j) keep += d[j] > drop * largest;
  // Y = V Q_kept D_kept^{-1/2}: then YᵀMY = D^{-1/2} Qᵀ G Q D^{-1/2} = I.
  const Eigen::MatrixXd T = eig.vectors.rightCols(keep) * d.tail(keep).cwiseSqrt().cwiseInverse().asDiagonal();
  return V * T;
}

Svd singularValueDecomposition(const Eigen::MatrixXd& M, SvdMethod method, unsigned vectors) {
  unsigned options = 0;
  if (vectors & kThinU) options |= Eigen::ComputeThinU;
  if (vectors & kThinV) options |= Eigen::ComputeThinV;
  if (method == SvdMethod::jacobi) return fromDecomposition(Eigen::JacobiSVD<Eigen::MatrixXd>(M, options), vectors);
  return fromDecomposition(Eigen::BDCSVD<Eigen::MatrixXd>(M, options), vectors);
}

Eigen::MatrixXd gaussianSketch(Eigen::Index rows, Eigen::Index cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd omega(rows, cols);
  for (Eigen::Index j = 0; j < omega.size(); ++j) omega(j) = normal(rng);
  return omega;
}

Eigen::MatrixXd randomizedRange(const Eigen::MatrixXd& R, Eigen::Index samples, int power_iterations,
                                unsigned seed) {
  return randomizedRange(R, gaussianSketch(R.cols(), samples, seed), power_iterations);
}

Eigen::MatrixXd randomizedRange(const Eigen::MatrixXd& R, const Eigen::Ref<const Eigen::MatrixXd>& omega,
                                int power_iterations) {
  Eigen::MatrixXd Q = orthonormalColumns(R * omega);
  for (int it = 0; it < power_iterations; ++it) Q = orthonormalColumns(R * (R.transpose() * Q));
  return Q;
}

}  // namespace stc::linalg
