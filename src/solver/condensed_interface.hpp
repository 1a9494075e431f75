#pragma once
// The problem condensed on the contact interface with one factorisation of K_ff:
// u(t_k) = K⁻¹ (f(t_k) + Bᵀ λ(t_k))  ⇒  v(t_k) = v_0(t_k) + W λ(t_k), with the Delassus operator
// W = B K⁻¹ Bᵀ and the free response v_0 = B K⁻¹ f. Used by the incremental solver and to measure
// true errors on the interface alone (δuᵀ K δu = δλᵀ W δλ when K δu = Bᵀ δλ).
#include <Eigen/Core>

#include "src/linalg/spd_factor.hpp"
#include "src/problem/problem.hpp"

namespace stc {

struct CondensedInterface {
  Eigen::MatrixXd delassus;       ///< W (2n_C × 2n_C), symmetric positive semi-definite
  Eigen::MatrixXd free_response;  ///< v_0 (2n_C × m)
  int sparse_solves = 0;          ///< right-hand sides it took (2n_C + number of load terms)

  static CondensedInterface build(const Problem& problem, const SpdFactor& stiffness_free);
};

/// Free displacements u(t_k) = K⁻¹ (f(t_k) + Bᵀ λ(t_k)) for every instant (n_free × m).
Eigen::MatrixXd displacementsFromForces(const Problem& problem, const SpdFactor& stiffness_free,
                                        const Eigen::MatrixXd& lambda);

}  // namespace stc
