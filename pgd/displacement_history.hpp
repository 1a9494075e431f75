#pragma once
// The snapshot matrix of docs/method.md §3: U = [u(t_0) … u(t_{m−1})] (n × m), the FULL nodal
// displacement at every instant (prescribed dofs included), rebuilt from a solution's contact
// forces: u_free(t_k) = K_ff⁻¹ (f(t_k) + Bᵀ λ(t_k)) (docs/method.md §1, eq. (1) of the seed), then the
// prescribed values u_d(t_k) put back (Problem::fullDisplacement).
#include <Eigen/Core>

#include "stcontact/linalg/spd_factor.hpp"
#include "stcontact/problem/problem.hpp"

namespace stc::pgd {

/// n × m full displacements for the contact forces `lambda` (d n_C × m), one multi-right-hand-side
/// solve with the factor of K_ff.
Eigen::MatrixXd fullDisplacementHistory(const Problem& problem, const SpdFactor& stiffness_free,
                                        const Eigen::MatrixXd& lambda);

}  // namespace stc::pgd
