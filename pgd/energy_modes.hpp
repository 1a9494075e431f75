#pragma once
// Spatial modes Υ_1 … Υ_r of the PGD expansion u(t_k) ≈ Σ_j Υ_j ψ_j(t_k) (docs/method.md §5), kept
// orthonormal in the energy product of A = K + Bᵀ k B (Υᵀ A Υ = I), with the products every update
// needs: B Υ (2n_C × r) and Υᵀ F (r × n_loads, F the separated load vectors).
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace stc::pgd {

class EnergyModes {
 public:
  /// `A` = K + Bᵀ k B, `B` the interface operator, `F` the load vectors (n_free × n_loads).
  EnergyModes(const Eigen::SparseMatrix<double>& A, const Eigen::SparseMatrix<double>& B, Eigen::MatrixXd F);

  /// A-orthogonalises `mode` against the modes (Gram–Schmidt, twice for round-off) and appends it,
  /// normalised. Returns false, and appends nothing, when what is left has an energy norm below
  /// `drop` times the original (the mode is already spanned).
  bool add(Eigen::VectorXd mode, double drop = 1e-10);

  int rank() const { return static_cast<int>(modes_.cols()); }
  const Eigen::MatrixXd& modes() const { return modes_; }           ///< Υ, n_free × r
  const Eigen::MatrixXd& interface() const { return interface_; }   ///< B Υ, 2n_C × r
  const Eigen::MatrixXd& loadProjection() const { return load_projection_; }  ///< Υᵀ F, r × n_loads
  const Eigen::MatrixXd& loads() const { return loads_; }           ///< F
  const Eigen::SparseMatrix<double>& energy() const { return A_; }  ///< A
  const Eigen::SparseMatrix<double>& interfaceOperator() const { return B_; }
  /// Largest |Υᵀ A Υ − I| entry (a check of the orthonormalisation).
  double orthonormalityDefect() const;

 private:
  const Eigen::SparseMatrix<double>& A_;
  const Eigen::SparseMatrix<double>& B_;
  Eigen::MatrixXd loads_, modes_, interface_, load_projection_;
};

}  // namespace stc::pgd
