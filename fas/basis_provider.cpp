#include "fas/basis_provider.hpp"

#include "fas/residual_vectors.hpp"

namespace stc::fas {

FixedBasisProvider::FixedBasisProvider(const Eigen::MatrixXd& vectors, int residual_vectors,
                                       const Eigen::SparseMatrix<double>& A, const Eigen::SparseMatrix<double>& B)
    : fixed_(vectors, A, B), residual_vectors_(residual_vectors), A_(A), B_(B) {}

CoarseSpace FixedBasisProvider::coarseSpace(const Eigen::MatrixXd& u_tilde, const InterfaceHistory& /*s*/) {
  const Eigen::MatrixXd res = residualVectors(u_tilde, fixed_.basis(), A_, residual_vectors_);
  if (res.cols() == 0) return fixed_;
  Eigen::MatrixXd all(fixed_.basis().rows(), fixed_.rank() + res.cols());
  all << fixed_.basis(), res;
  return CoarseSpace(all, A_, B_);
}

}  // namespace stc::fas
