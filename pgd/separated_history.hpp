#pragma once
// The displacement history of an iterate of the separated global stage,
//   u_k = U_F g_k + X c_k = Φ θ_k,   Φ = [U_F X] (n_free × s),  θ_k = [g_k; c_k],  s = q + p,
// and its singular value decomposition in the energy product of A = K_ff + Bᵀ k B, without an
// n_free × m array (docs/method.md §5, "Recompression"; the idea of Giacoma, Dureisseix, Gravouil,
// AMSES 2016: the SVD of a separated expansion from its small factors). With the Cholesky factor
// ΦᵀAΦ = RᵀR kept by the response basis (pgd/energy_factor.hpp), Φ̂ = Φ R⁻¹ is A-orthonormal and
// u = Φ̂ Θ̂ with Θ̂ = R Θ (s' × m). The SVD Θ̂ = U Σ Wᵀ gives the A-orthonormal modes Y = Φ̂ U, their
// energies σ_i², time functions Σ Wᵀ and traces B Y = [V_F T] R⁻¹ U: it is the energy SVD of u
// itself, converged as soon as the expansion is. The leading singular vectors come from a
// randomized range finder with subspace iterations (leadingSingularVectors), at O(s' m r) cost.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "stcontact/pgd/response_basis.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::pgd {

/// Θ = [G; c] of the history with interface coordinates `c` (p × m, p ≤ basis.size(); missing rows
/// are zero), s × m.
Eigen::MatrixXd historyFactor(const ResponseBasis& basis, const Eigen::MatrixXd& c);

/// Θ̂ = R Θ, the history's energy coordinates (EnergyFactor::whiten of historyFactor): u = Φ̂ Θ̂
/// with Φ̂ A-orthonormal, so the A-product of histories is the Euclidean one of their Θ̂.
Eigen::MatrixXd whitenedHistory(const ResponseBasis& basis, const Eigen::MatrixXd& c);

/// The leading `count` left singular vectors of `coordinates` (s' × m), fewer if its rank is
/// smaller (singular values below `drop` times the largest are left out). Halko, Martinsson &
/// Tropp, SIAM Review 53 (2011), alg. 4.4 (range finder with q = 2 subspace iterations, 10 extra
/// samples, a fixed seed: deterministic) and alg. 5.1 (the SVD of the small projected matrix, by
/// Eigen's BDCSVD). When count + 10 reaches s' or m the range is the whole row or column space
/// and the result is the exact SVD's.
Eigen::MatrixXd leadingSingularVectors(const Eigen::MatrixXd& coordinates, int count, double drop = 1e-12);

struct EnergySvd {
  Eigen::MatrixXd combination;     ///< s × r: the modes are Y = [U_F X] · combination, YᵀAY = I
  Eigen::VectorXd singular_values; ///< σ_i, decreasing: Σσ_i² = Σ_k u_kᵀ A u_k
  Eigen::MatrixXd time_functions;  ///< r × m
};

/// The energy SVD of the history (modes with σ_i > `drop` σ_1, at most `count`).
EnergySvd energySvd(const ResponseBasis& basis, const Eigen::MatrixXd& c, int count, double drop = 1e-12);

/// The spatial modes Y = [U_F X] · combination (n_free × r): for output and warm starts only.
Eigen::MatrixXd spatialModes(const ResponseBasis& basis, const Eigen::MatrixXd& combination);
/// Their traces B Y = [V_F T] · combination (d n_C × r).
Eigen::MatrixXd modeTraces(const ResponseBasis& basis, const Eigen::MatrixXd& combination);

/// ρ: the fewest leading modes of singular values σ (decreasing) whose dropped energy
/// Σ_{i>ρ} σ_i² is at most `energy_budget` (every mode for a budget below the smallest σ_i²).
Eigen::Index modesWithinBudget(const Eigen::VectorXd& singular_values, double energy_budget);

/// The energy a converged solve may still spend on truncations of its outputs (the far nodes' lift,
/// the separated displacement): with the last record's estimate e ≤ τ and history energy E,
/// (τ − e)² E, so that the truncated history's relative error stays within τ; 0 for a solve that did
/// not converge or has no energy on record.
double truncationBudget(const SolveSummary& summary, double tolerance);

/// The history with interface coordinates `c` in separated form (SolveResult::displacement): the
/// fewest ρ leading modes of its energy SVD whose dropped energy Σ_{i>ρ} σ_i² = Σ_k ‖u_k − u_ρ,k‖²_A
/// is at most `energy_budget` (every mode for a budget ≤ 0), the modes Y_ρ = [U_F X] C_ρ (at most ρ
/// solves, none when the responses are known) and their time functions Σ_ρ W_ρᵀ.
SeparatedDisplacement separatedDisplacement(const ResponseBasis& basis, const Eigen::MatrixXd& c, double energy_budget);

/// Every mode of the energy SVD of the history (n_free × r): SolveResult::spatial_modes.
Eigen::MatrixXd energyModes(const ResponseBasis& basis, const Eigen::MatrixXd& c);

}  // namespace stc::pgd
