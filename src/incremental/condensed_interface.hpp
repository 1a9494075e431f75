#pragma once
// The problem condensed on the contact interface with one factorisation of K_ff:
// u(t_k) = K⁻¹ (f(t_k) + Bᵀ λ(t_k))  ⇒  v(t_k) = v_0(t_k) + W λ(t_k), with the Delassus operator
// W = B K⁻¹ Bᵀ and the free response v_0 = B K⁻¹ f. Used by the incremental solver and to measure
// true errors on the interface alone (δuᵀ K δu = δλᵀ W δλ when K δu = Bᵀ δλ).
#include <Eigen/Core>

#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/problem/problem.hpp"

namespace stc {

struct CondensedInterface {
  Eigen::MatrixXd delassus;       ///< W (d n_C × d n_C), symmetric positive semi-definite
  Eigen::MatrixXd free_response;  ///< v_0 (d n_C × m)
  int sparse_solves = 0;          ///< right-hand sides it took (d n_C + number of load terms)

  static CondensedInterface build(const Problem& problem, const SpdSolver& stiffness_free);
};

/// W = B K⁻¹ Bᵀ from the responses K⁻¹ Bᵀ, made symmetric to round-off.
Eigen::MatrixXd symmetricDelassus(const Eigen::SparseMatrix<double>& B, const Eigen::MatrixXd& responses);

/// A held row r of node i (ContactInterface::held_rows: no free dof moves the node along its
/// tangent) has W(r, ·) = 0 and W(·, r) = 0, which leaves λ_r undetermined in a stick Newton system.
/// The incremental solvers give it the compliance of the node's normal row, W(r, r) = W(d i, d i),
/// which changes no motion (B's row r is empty) and makes the law decide λ_r = 0: sticking,
/// Δv_r = W(r, r) Δλ_r = 0; slipping, λ_r = −μ λ_n Δv_r / |Δv_t| has the sign opposite to
/// Δv_r = W(r, r) λ_r (from λ_r = 0 at t_0, by induction). The support takes the force.
void giveHeldRowsCompliance(const ContactInterface& contact, Eigen::MatrixXd& delassus);

}  // namespace stc
