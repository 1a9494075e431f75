#pragma once
// The coarse space of the two-level FAS (seed eqs. (2), (7), (8)): P = Y, R = Pᵀ, R̄ = Yᵀ, with Y
// orthonormal in the product of A = K + Bᵀ k B, so that the coarse operator R A P is the identity
// and the coarse linear stage is a product with (BY)ᵀ (docs/method.md §4: "beside r × r algebra only
// B P and Pᵀ(K + BᵀkB)P are needed").
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace stc::fas {

class CoarseSpace {
 public:
  CoarseSpace() = default;
  /// A-orthonormalises the columns of `vectors` (n_free × q) by linalg::orthonormalIn: eigen-decomposition
  /// of the Gram matrix G = VᵀAV, dropping directions with eigenvalue below `drop` · max (dependent vectors).
  CoarseSpace(const Eigen::MatrixXd& vectors, const Eigen::SparseMatrix<double>& A,
              const Eigen::SparseMatrix<double>& B, double drop = 1e-12);
  /// A space whose basis Y is A-orthonormal by construction and kept in separated form
  /// (pgd/separated_history.hpp): only its traces B Y (d n_C × r) are given; basis() is empty.
  static CoarseSpace fromTraces(Eigen::MatrixXd traces);

  int rank() const { return static_cast<int>(BY_.cols()); }
  const Eigen::MatrixXd& basis() const { return Y_; }       ///< Y, n_free × r, YᵀAY = I (may be empty)
  const Eigen::MatrixXd& interface() const { return BY_; }  ///< B Y, d n_C × r
  /// Largest |YᵀAY − I| entry (a check of the orthonormalisation).
  double orthonormalityDefect(const Eigen::SparseMatrix<double>& A) const;

 private:
  Eigen::MatrixXd Y_, BY_;
};

}  // namespace stc::fas
