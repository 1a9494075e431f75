#pragma once
// A posteriori space-time SVD of a displacement history (docs/method.md §3; seed paper §3.1, Figs. 2–3):
//   U = [u(t_0) … u(t_{m−1})] = Σ_i σ_i Υ_i ν_iᵀ,   Υ_iᵀ M Υ_j = δ_ij,   ν_iᵀ ν_j = δ_ij,
// with M = I (plainSvd) or M = K, the full unconstrained stiffness (energySvd), so that
//   Σ_i σ_i² = ‖U‖²_K = Σ_k u_kᵀ K u_k,
// the elastic energy summed over the time grid (twice it: the factor ½ is left out everywhere),
// and "modes for 99.9 % of the energy" means what the seed means. Verification only: never on a
// solve path (docs/method.md §5).
//
// Energy SVD through the m × m Gram matrix (the "method of snapshots"): C = Uᵀ K U = V Σ² Vᵀ, so
// σ_i² are the eigenvalues of C, ν_i its eigenvectors and Υ_i = U ν_i / σ_i. Dense: Eigen's
// SelfAdjointEigenSolver on the formed C. Truncated: ARPACK (pgd/arpack_eigen.hpp), 'LA', on the
// operator x ↦ Uᵀ(K(U x)) / ‖U‖²_K, never forming C (the scaling by the total puts the spectrum in
// [0, 1]; ARPACK's convergence floor ε^{2/3} then reads as a fraction of the total energy).
//
// Resolution. Squaring costs accuracy: the computed eigenvalues carry absolute errors of order
// m·ε·λ_1, hence σ_i carries a relative error ~ ½ m ε (σ_1/σ_i)², and σ_i below σ_1 √(m ε)
// (≈ 2e-7 σ_1 for m = 201) is round-off. Those modes keep their σ_i (a noise level, not a value)
// but get Υ_i = 0: `resolved` counts the modes above the floor.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <optional>

namespace stc::pgd {

enum class SvdMethod {
  Dense,   ///< all m eigenpairs of the formed Gram matrix (Eigen), O(m³): small m, tests, checks
  Arpack,  ///< the leading `modes` pairs by ARPACK, matrix-free: O(modes · (n·m + nnz(K))) per Lanczos step
};

struct EnergySvdOptions {
  /// Dense is exact and cheap up to m of a few thousand; ARPACK is what scales (docs/architecture.md).
  SvdMethod method = SvdMethod::Dense;
  /// Leading pairs to return; 0 = all m (Dense only). ARPACK needs 1 ≤ modes ≤ m − 1.
  int modes = 0;
  /// ARPACK's relative tolerance on the Ritz values; 0 = machine precision.
  double tolerance = 0.0;
  /// ARPACK's NCV; 0 = min(m, 2·modes + 1).
  int subspace = 0;
  /// ARPACK's restart cap (see ArpackOptions::max_restarts).
  int max_restarts = 3000;

  /// Throws InputError naming the field, its value and the rule, for a history of m instants.
  void validate(int m) const;
};

struct SpaceTimeSvd {
  Eigen::VectorXd sigma;  ///< σ_1 ≥ σ_2 ≥ … ≥ 0 (r values)
  Eigen::MatrixXd space;  ///< Υ (n × r), orthonormal in the product M; zero columns from `resolved` on
  Eigen::MatrixXd time;   ///< ν (m × r), orthonormal; sign fixed by a positive largest-|·| entry
  double total_energy = 0.0;  ///< ‖U‖²_M = Σ over all m of σ_i², known even when r < m
  int resolved = 0;           ///< modes above the round-off floor (see the header comment)
  int operator_applications = 0;  ///< ARPACK's y = C x products (0 for dense methods)

  int size() const { return static_cast<int>(sigma.size()); }
  /// σ_i² / ‖U‖²_M, the share of the space-time energy carried by pair i (0-based).
  double energyFraction(int i) const;
  /// Σ_{j ≤ i} σ_j² / ‖U‖²_M.
  double cumulativeEnergy(int i) const;
  /// Smallest count of leading pairs whose cumulative share reaches `fraction` (e.g. 0.999), or
  /// nothing if the computed pairs do not reach it.
  std::optional<int> modesFor(double fraction) const;
  /// Σ_{i < r} σ_i Υ_i ν_iᵀ (n × m).
  Eigen::MatrixXd reconstruct(int r) const;
};

/// Euclidean SVD (M = I) with Eigen's BDCSVD; `modes` leading pairs (0 = min(n, m)).
SpaceTimeSvd plainSvd(const Eigen::MatrixXd& U, int modes = 0);

/// SVD in the energy product of the symmetric positive semi-definite K (n × n), U of n rows.
/// Throws InputError on inconsistent sizes or options, std::runtime_error if ARPACK fails.
SpaceTimeSvd energySvd(const Eigen::MatrixXd& U, const Eigen::SparseMatrix<double>& K,
                       const EnergySvdOptions& options = {});

/// ‖U‖²_K = Σ_k u_kᵀ K u_k, accumulated column by column.
double squaredEnergyNorm(const Eigen::MatrixXd& U, const Eigen::SparseMatrix<double>& K);

}  // namespace stc::pgd
