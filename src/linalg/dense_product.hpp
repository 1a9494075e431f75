#pragma once
// Dense products of long histories written without a zeroing pass. Eigen evaluates C = A B as
// C = 0, then C += A B (its GEMM, or BLAS's dgemm with β = 1): on a long history the zeroing is a
// pass of its own over memory most often touched for the first time. Here C = A B is one dgemm
// with β = 0, which writes C without reading it (at 10 001 instants the far nodes' lift of
// fas-apriori, 8436 × 10 001, is one such product; fretting, divisions 16). Where the BLAS takes
// concurrent calls (OpenBLAS's pthread build, blas_kernels.hpp) a large product is split into
// ranges of columns on the threads, each column's arithmetic that of one dgemm: the same bits on any
// number of threads (docs/threads.md, "OpenBLAS's pthread build"); with OpenBLAS's serial
// build, one dgemm on the calling thread.
#include <Eigen/Core>

namespace stc::linalg {

/// C = A B, C resized to A.rows() × B.cols(), its entries written, never read (C is neither A nor B).
void multiply(const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::MatrixXd>& B,
              Eigen::MatrixXd& C);

/// C = Aᵀ B, as multiply.
void multiplyTransposed(const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::MatrixXd>& B,
                        Eigen::MatrixXd& C);

/// C += A B (dgemm with β = 1, as Eigen's C.noalias() += A * B), split as multiply. C must be
/// A.rows() × B.cols() and neither A nor B.
void multiplyAdd(const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::MatrixXd>& B,
                 Eigen::MatrixXd& C);

/// A B in a new matrix (multiply).
Eigen::MatrixXd freshProduct(const Eigen::Ref<const Eigen::MatrixXd>& A, const Eigen::Ref<const Eigen::MatrixXd>& B);

}  // namespace stc::linalg
