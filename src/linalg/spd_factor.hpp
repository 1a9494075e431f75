#pragma once
// One sparse Cholesky factorisation (CHOLMOD, supernodal, through Eigen's CholmodSupport) reused for
// many solves: METHOD.md §2 "factorize once, then one multi-right-hand-side solve per iteration".
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>

namespace stc {

class SpdFactor {
 public:
  /// Factorises A (symmetric positive definite, lower triangle used). Throws InputError naming
  /// `what` if A is not positive definite (e.g. Dirichlet conditions that leave a rigid motion free).
  SpdFactor(const Eigen::SparseMatrix<double>& A, const std::string& what);
  ~SpdFactor();
  SpdFactor(SpdFactor&&) noexcept;
  SpdFactor& operator=(SpdFactor&&) noexcept;

  /// X = A⁻¹ B for all columns of B at once (one CHOLMOD call).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  int size() const;
  /// Entries of the Cholesky factor L as CHOLMOD's analysis counts them (cholmod_common::lnz:
  /// without the explicit zeros of supernodal amalgamation): its memory is about 8 bytes each.
  double factorNonZeros() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace stc
