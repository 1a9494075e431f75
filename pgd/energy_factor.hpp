#pragma once
// The Cholesky factor of the energy Gram matrix M = ΦᵀAΦ of the separated history's spatial
// factor Φ = [U_F X] (pgd/response_basis.hpp), kept up to date column by column as directions are
// appended (they never change once added), so that whitening costs O(s²) per new column instead
// of a decomposition of M at every coarse step.
//   M = Rᵀ R,  R upper triangular:  Φ̂ = Φ_K R_K⁻¹ is A-orthonormal and Φ = Φ̂ R
// (Φ̂ is the Gram–Schmidt orthonormalisation of Φ in the A-product, in column order; Golub & Van
// Loan, Matrix Computations, §4.2.5 and §5.2.8: Cholesky of the Gram matrix is the R of a QR).
// A column whose energy outside the span of the earlier ones is below `drop_` = 1e-14 of its own
// energy (a dependent column, to 1e-7 in norm) gets no row of its own: R has s' ≤ s rows, and K
// lists the columns that have one. Every coordinate map goes through R: Θ̂ = R Θ (s' × m) are the
// coordinates of u = ΦΘ in the A-orthonormal Φ̂.
#include <Eigen/Core>
#include <vector>

namespace stc::pgd {

class EnergyFactor {
 public:
  /// Appends the column j = size() of Φ given its energy products with every column so far and
  /// itself: `products` = Φᵀ A φ_j (j + 1 entries, the last one φ_jᵀ A φ_j).
  void append(const Eigen::VectorXd& products);
  /// Appends b columns at once, the same factor as b calls of append to round-off: `products`
  /// ((size() + b) × b), column a holding Φᵀ A φ_{size()+a} in its first size() + a + 1 entries (the
  /// rest is not read). Their coefficients on Φ̂ come from one triangular solve with b right-hand
  /// sides, their own rows from the Cholesky factor of the Schur complement of their block, or
  /// column by column (append) when one of them is dependent.
  void appendBlock(const Eigen::MatrixXd& products);

  int size() const { return size_; }                          ///< s: columns of Φ
  int rank() const { return static_cast<int>(kept_.size()); } ///< s': rows of R
  /// R (s' × s): the coordinates of Φ's columns in Φ̂.
  Eigen::Block<const Eigen::MatrixXd> coordinatesOfColumns() const { return R_.topLeftCorner(rank(), size_); }
  /// Θ̂ = R Θ for coordinates Θ (s × m, or fewer rows: the missing ones are zero).
  Eigen::MatrixXd whiten(const Eigen::MatrixXd& theta) const;
  /// The combination C (s × r) with Φ C = Φ̂ U for whitened coordinates U (s' × r): C = P_K R_K⁻¹ U.
  Eigen::MatrixXd combination(const Eigen::MatrixXd& U) const;
  /// Φ̂ᵀ A Y (s' × k) for vectors Y given their products `products` = Φᵀ A Y (s × k): the coordinates
  /// in Φ̂ of their A-orthogonal projections on span Φ. Φ̂ = Φ_K R_K⁻¹, so Φ̂ᵀ A Y = R_K⁻ᵀ (Φᵀ A Y)_K.
  Eigen::MatrixXd projections(const Eigen::MatrixXd& products) const;

 private:
  Eigen::MatrixXd R_;          ///< storage with spare capacity (doubling); R is its top-left s' × s
  Eigen::MatrixXd RK_;         ///< R_K = R(:, K), s' × s' upper triangular, in the same kind of storage
  int size_ = 0;
  std::vector<int> kept_;      ///< K: the columns with a row of R, in order
  static constexpr double drop_ = 1e-14;
};

}  // namespace stc::pgd
