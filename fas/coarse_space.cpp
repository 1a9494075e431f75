#include "stcontact/fas/coarse_space.hpp"

#include "stcontact/linalg/dense_decompositions.hpp"

namespace stc::fas {

CoarseSpace::CoarseSpace(const Eigen::MatrixXd& vectors, const Eigen::SparseMatrix<double>& A,
                         const Eigen::SparseMatrix<double>& B, double drop) {
  if (vectors.cols() == 0) {
    Y_.resize(A.rows(), 0);
    BY_.resize(B.rows(), 0);
    return;
  }
  Y_ = linalg::orthonormalIn(vectors, A, drop);
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
