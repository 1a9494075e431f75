#include "stcontact/linalg/dense_product.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "stcontact/core/threads.hpp"
#include "stcontact/core/worker_pool.hpp"
#include "stcontact/linalg/blas_kernels.hpp"

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

// C = op(A) B + β C by one dgemm (β = 0: C written, not read). Without BLAS, Eigen's product.
void gemm(const Operand& op, const Eigen::Ref<const Eigen::MatrixXd>& B, Eigen::Ref<Eigen::MatrixXd> C, double beta) {
  const Eigen::Ref<const Eigen::MatrixXd>& A = op.A;
#ifdef EIGEN_USE_BLAS
  constexpr Eigen::Index kMax = std::numeric_limits<int>::max();  // BLAS's dimensions are int
  if (A.rows() <= kMax && A.cols() <= kMax && B.cols() <= kMax && A.outerStride() <= kMax &&
      B.outerStride() <= kMax && C.outerStride() <= kMax) {
    const int m = static_cast<int>(op.rows()), n = static_cast<int>(B.cols()), k = static_cast<int>(op.inner());
    const int lda = static_cast<int>(std::max<Eigen::Index>(A.outerStride(), 1));
    const int ldb = static_cast<int>(std::max<Eigen::Index>(B.outerStride(), 1));
    const int ldc = static_cast<int>(std::max<Eigen::Index>(C.outerStride(), 1));
    const double alpha = 1.0;
    dgemm_(op.transposed ? "T" : "N", "N", &m, &n, &k, &alpha, A.data(), &lda, B.data(), &ldb, &beta, C.data(), &ldc);
    return;
  }
#endif
  if (beta == 0.0) C.setZero();
  if (op.transposed)
    C.noalias() += A.transpose() * B;
  else
    C.noalias() += A * B;
}

// Column ranges of a split product start at multiples of kColumnGrain: every column count OpenBLAS's
// x86-64 dgemm kernels take at once (4 to 24) divides it, so each column meets the same kernel
// calls as in one dgemm (docs/threads.md, "OpenBLAS's pthread build"). A range is split off
// only with more than kSmallProduct multiply-adds: OpenBLAS 0.3.21 takes other kernels for products
// of at most 100³ (its small-matrix path), which would change the range's last bits.
constexpr Eigen::Index kColumnGrain = 192;
constexpr double kSmallProduct = 1e6;

// The number of column ranges to split op(A) B into: 1 unless the BLAS takes concurrent calls,
// threads are there and the smallest range has more than kSmallProduct multiply-adds.
int columnRanges(const Operand& op, Eigen::Index columns) {
  const int threads = threadCount();
  if (threads < 2 || detail::WorkerPool::insideRun() || !blasTakesConcurrentCalls()) return 1;
  const Eigen::Index grains = columns / kColumnGrain;
  const double per_grain = static_cast<double>(op.rows()) * static_cast<double>(op.inner()) * kColumnGrain;
  auto ranges = static_cast<int>(std::min<Eigen::Index>(threads, grains));
  while (ranges > 1 && static_cast<double>(grains / ranges) * per_grain <= kSmallProduct) --ranges;
  return std::max(ranges, 1);
}

// C = op(A) B + β C, over column ranges on the threads when columnRanges says so: parallelRanges'
// ranges of kColumnGrain-column grains, the last range also the columns after the last grain.
void splitGemm(const Operand& op, const Eigen::Ref<const Eigen::MatrixXd>& B, Eigen::Ref<Eigen::MatrixXd> C, double beta) {
  const int ranges = columnRanges(op, B.cols());
  if (ranges == 1) return gemm(op, B, C, beta);
  const auto grains = static_cast<int>(B.cols() / kColumnGrain);
  parallelRanges(grains, ranges, [&](int first, int last) {
    const Eigen::Index begin = first * kColumnGrain, end = last == grains ? B.cols() : last * kColumnGrain;
    gemm(op, B.middleCols(begin, end - begin), C.middleCols(begin, end - begin), beta);
  });
}

void multiplyInto(const Operand& op, const Eigen::Ref<const Eigen::MatrixXd>& B, Eigen::MatrixXd& C) {
  requireShapes(op, B);
  C.resize(op.rows(), B.cols());
  if (C.size() == 0) return;
  if (op.inner() == 0) {
    C.setZero();
    return;
  }
  splitGemm(op, B, C, 0.0);
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

void multiplyAdd(const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::MatrixXd>& B,
                 Eigen::MatrixXd& C) {
  const Operand op{A, false};
  requireShapes(op, B);
  if (C.rows() != A.rows() || C.cols() != B.cols())
    throw std::invalid_argument("dense product: C += A B needs C of A's rows and B's columns");
  if (C.size() == 0 || op.inner() == 0) return;
  splitGemm(op, B, C, 1.0);
}

Eigen::MatrixXd freshProduct(const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::MatrixXd>& B) {
  Eigen::MatrixXd C;
  multiply(A, B, C);
  return C;
}

}  // namespace stc::linalg
