#include "fas/coarse_space.hpp"

#include "src/linalg/dense_decompositions.hpp"

namespace stc::fas {

CoarseSpace::CoarseSpace(const Eigen::MatrixXd& vectors, const Eigen::SparseMatrix<double>& A,
                         const Eigen::SparseMatrix<double>& B, double drop) {
  if (vectors.cols() == 0) {
    Y_.resize(A.rows(), 0);
    BY_.resize(B.rows(), 0);
    return;
  }
  const Eigen::MatrixXd AV = A * vectors;
  Eigen::MatrixXd G = vectors.transpose() * AV;
  G = 0.5 * (G + G.transpose()).eval();
  const linalg::SymmetricEigen eig = linalg::symmetricEigen(G);
  const Eigen::VectorXd& d = eig.values;  // ascending
  const double largest = d.maxCoeff();
  int keep = 0;
  for (Eigen::Index j = 0; j < d.size(); ++j) keep += d[j] > drop * largest;
  // Y = V Q_kept D_kept^{-1/2}: then YᵀAY = D^{-1/2} Qᵀ G Q D^{-1/2} = I.
  const Eigen::MatrixXd T = eig.vectors.rightCols(keep) *
                            d.tail(keep).cwiseSqrt().cwiseInverse().asDiagonal();
  Y_ = vectors * T;
  BY_ = B * Y_;
}

CoarseSpace CoarseSpace::fromTraces(Eigen::MatrixXd traces) {
  CoarseSpace space;
  space.BY_ = std::move(traces);
  return space;
}

double CoarseSpace::orthonormalityDefect(const Eigen::SparseMatrix<double>& A) const {
  const Eigen::MatrixXd G = Y_.transpose() * (A * Y_);
  return (G - Eigen::MatrixXd::Identity(rank(), rank())).cwiseAbs().maxCoeff();
}

}  // namespace stc::fas
