#pragma once
// The state of one contact node at one instant (docs/method.md §1), read off a solution for the output
// writers and the contact-law check: open (no force), stick (inside the Coulomb cone, no slip) or
// slip (on the cone, slipping).
namespace stc {

enum class ContactState { Open, Stick, Slip };

/// "open", "stick", "slip".
const char* toString(ContactState state);

/// Relative tolerances of classifyContact, chosen far above the round-off of a solution converged
/// to ~1e-13 (the incremental solver) and far below what any state change looks like.
namespace contact_state_tolerance {
inline constexpr double open_force = 1e-10;  ///< open if λ_n ≤ open_force · force_scale
inline constexpr double cone = 1e-8;         ///< on the cone if |λ_t| ≥ μ λ_n (1 − cone)
inline constexpr double slip = 1e-12;        ///< slipping if |Δv_t| > slip · length_scale
}  // namespace contact_state_tolerance

/// Classifies one node at one instant from its forces (λ_n, λ_t), its slip increment
/// Δv_t = v_t(t_k) − v_t(t_{k−1}) and the friction coefficient μ (docs/method.md §1):
///   open  if λ_n ≤ 1e-10 · force_scale (force_scale: e.g. the largest λ_n of the history);
///   slip  if |λ_t| ≥ μ λ_n (1 − 1e-8) and |Δv_t| > 1e-12 · length_scale (e.g. the largest |v|);
///   stick otherwise (a node on the cone that does not move is sticking at impending slip).
/// A node with |λ_t| strictly inside the cone that slips breaks the law; it is reported as stick
/// here and caught by checkContactLaw (src/solver/contact_law_check.hpp).
ContactState classifyContact(double lambda_n, double lambda_t, double slip, double mu, double force_scale,
                             double length_scale);

}  // namespace stc
