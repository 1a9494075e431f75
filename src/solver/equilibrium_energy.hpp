#pragma once
// The elastic energy over the time grid, E = Σ_k u_kᵀ K u_k (full field, full K: the normalisation
// of the true error, docs/method.md §2), of an equilibrated interface iterate s = (v, λ), computed on
// the interface alone. For such an iterate K_ff u_k = F g_k + Bᵀ λ_k (loads in separated form,
// Problem::loads), so with A = K_ff + Bᵀ k B and w_k = λ_k + k v_k:
//   u_k = A⁻¹ (F g_k + Bᵀ w_k),      a ᵀ u_k = (A⁻¹a)ᵀ F g_k + (B A⁻¹ a)ᵀ w_k   for any vector a,
//   E_k = u_kᵀ K_ff u_k + 2 u_kᵀ D g_k + g_kᵀ Pᵀ K P g_k,   u_kᵀ K_ff u_k = (Fᵀu_k)·g_k + v_k·λ_k,
// where P holds the prescribed parts of the load terms (full field) and D = K_fP P their coupling
// with the free dofs. Set-up: one solve with A per column of [F D]; then O(q n_C m) per call.
#include <Eigen/Core>

#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc {

class EquilibriumEnergy {
 public:
  /// `search_factor` factorises A = K_ff + Bᵀ k B with k = problem.contact.search_direction.
  EquilibriumEnergy(const Problem& problem, const SpdSolver& search_factor);

  /// E = Σ_k u_kᵀ K u_k of the equilibrated iterate s.
  double operator()(const InterfaceHistory& s) const;
  /// The problem whose iterates it measures (its contact interface: the rows of the iterates).
  const Problem& problem() const { return problem_; }
  /// Sparse solves spent at set-up.
  int sparseSolves() const { return static_cast<int>(load_vectors_.cols()); }

 private:
  const Problem& problem_;
  Eigen::MatrixXd load_vectors_;     ///< [F D], n_free × 2q
  Eigen::MatrixXd load_responses_;   ///< (A⁻¹[F D])ᵀ F, 2q × q
  Eigen::MatrixXd interface_traces_; ///< B A⁻¹ [F D], d n_C × 2q
  Eigen::MatrixXd histories_;        ///< G, q × m
  Eigen::MatrixXd prescribed_energy_;///< Pᵀ K P, q × q
};

}  // namespace stc
