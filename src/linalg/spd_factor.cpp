#include "src/linalg/spd_factor.hpp"

#include <Eigen/CholmodSupport>

#include "src/core/input_error.hpp"

namespace stc {

struct SpdFactor::Impl {
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
  int n = 0;
};

SpdFactor::SpdFactor(const Eigen::SparseMatrix<double>& A, const std::string& what)
    : impl_(std::make_unique<Impl>()) {
  impl_->n = static_cast<int>(A.rows());
  impl_->llt.compute(A);
  if (impl_->llt.info() != Eigen::Success)
    throw InputError(what + " is not positive definite (do the Dirichlet conditions fix every rigid-body motion?)");
}

SpdFactor::~SpdFactor() = default;
SpdFactor::SpdFactor(SpdFactor&&) noexcept = default;
SpdFactor& SpdFactor::operator=(SpdFactor&&) noexcept = default;

Eigen::MatrixXd SpdFactor::solve(const Eigen::MatrixXd& B) const { return impl_->llt.solve(B); }
Eigen::VectorXd SpdFactor::solve(const Eigen::VectorXd& b) const { return impl_->llt.solve(b); }
int SpdFactor::size() const { return impl_->n; }

}  // namespace stc
