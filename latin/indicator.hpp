#pragma once
// LATIN error indicator (docs/method.md §2): η = ‖s − ŝ‖ / (½ ‖s + ŝ‖) with
// ‖s‖² = Σ_k Σ_i (v_iᵀ k_i v_i + λ_iᵀ k_i⁻¹ λ_i), the energy norm of the search direction.
#include <Eigen/Core>

#include "stcontact/spacetime/interface_history.hpp"

namespace stc::latin {

/// ‖(v, λ)‖² in the search-direction norm; k holds (k_n, k_t) per node.
double searchNormSquared(const Eigen::VectorXd& k, const Eigen::MatrixXd& v, const Eigen::MatrixXd& lambda);

/// η; when `gap` is given it receives ‖s − ŝ‖ (the numerator).
double indicator(const Eigen::VectorXd& k, const InterfaceHistory& s, const InterfaceHistory& hat,
                 double* gap = nullptr);

}  // namespace stc::latin
