#include "stcontact/linalg/dense_product.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

// With EIGEN_USE_BLAS, <Eigen/Core> declares the BLAS routines (Eigen/src/misc/blas.h): dgemm_.

namespace stc::linalg {
namespace {

// op(A) = A, or Aᵀ when `transposed`.
struct Operand {
  const Eigen::Ref<const Eigen::MatrixXd>& A;
  bool transposed;
  Eigen::Index rows() const { return transposed ? A.cols() : A.rows(); }
  Eigen::Index inner() const { return transposed ? A.rows() : A.cols(); }
};

void requireShapes(const Operand& op, const Eigen::Ref<const Eigen::MatrixXd>& B) {
  if (op.inner() != B.rows()) throw std::invalid_argument("dense product: op(A) has not as many columns as B has rows");
}

// C = op(A) B by one dgemm with β = 0 (C not read), on this thread: Debian's serial OpenBLAS is not
// safe for concurrent calls (docs/threads.md). Without BLAS, Eigen's product.
void gemm(const Operand& op, const Eigen::Ref<const Eigen::MatrixXd>& B, Eigen::MatrixXd& C) {
  const Eigen::Ref<const Eigen::MatrixXd>& A = op.A;
#ifdef EIGEN_USE_BLAS
  constexpr Eigen::Index kMax = std::numeric_limits<int>::max();  // BLAS's dimensions are int
  if (A.rows() <= kMax && A.cols() <= kMax && B.cols() <= kMax && A.outerStride() <= kMax &&
      B.outerStride() <= kMax && C.rows() <= kMax) {
    const int m = static_cast<int>(op.rows()), n = static_cast<int>(B.cols()), k = static_cast<int>(op.inner());
    const int lda = static_cast<int>(std::max<Eigen::Index>(A.outerStride(), 1));
    const int ldb = static_cast<int>(std::max<Eigen::Index>(B.outerStride(), 1));
    const int ldc = std::max(m, 1);
    const double alpha = 1.0, beta = 0.0;
    dgemm_(op.transposed ? "T" : "N", "N", &m, &n, &k, &alpha, A.data(), &lda, B.data(), &ldb, &beta, C.data(), &ldc);
    return;
  }
#endif
  if (op.transposed)
    C.noalias() = A.transpose() * B;
  else
    C.noalias() = A * B;
}

void multiplyInto(const Operand& op, const Eigen::Ref<const Eigen::MatrixXd>& B, Eigen::MatrixXd& C) {
  requireShapes(op, B);
  C.resize(op.rows(), B.cols());
  if (C.size() == 0) return;
  if (op.inner() == 0) {
    C.setZero();
    return;
  }
  gemm(op, B, C);
}

}  // namespace

void multiply(const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::MatrixXd>& B,
              Eigen::MatrixXd& C) {
  multiplyInto({A, false}, B, C);
}

void multiplyTransposed(const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::MatrixXd>& B,
                        Eigen::MatrixXd& C) {
  multiplyInto({A, true}, B, C);
}

Eigen::MatrixXd freshProduct(const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::MatrixXd>& B) {
  Eigen::MatrixXd C;
  multiply(A, B, C);
  return C;
}

}  // namespace stc::linalg
