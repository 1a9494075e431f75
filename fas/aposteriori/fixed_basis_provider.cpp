#include "stcontact/fas/aposteriori/fixed_basis_provider.hpp"

#include "stcontact/fas/residual_vectors.hpp"

namespace stc::fas {

FixedBasisProvider::FixedBasisProvider(const Eigen::MatrixXd& vectors, int residual_vectors,
                                       const latin::GlobalStage& global, const Eigen::SparseMatrix<double>& B)
    : fixed_(vectors, global.matrix(), B), residual_vectors_(residual_vectors), global_(global), B_(B) {}

CoarseSpace FixedBasisProvider::coarseSpace(const InterfaceHistory& /*hat*/) {
  const Eigen::SparseMatrix<double>& A = global_.matrix();
  const Eigen::MatrixXd res = residualVectors(global_.displacements(), fixed_.basis(), A, residual_vectors_);
  if (res.cols() == 0) return fixed_;
  Eigen::MatrixXd all(fixed_.basis().rows(), fixed_.rank() + res.cols());
  all << fixed_.basis(), res;
  return CoarseSpace(all, A, B_);
}

}  // namespace stc::fas
