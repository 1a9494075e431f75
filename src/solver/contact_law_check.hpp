#pragma once
// How far an interface history is from the discrete contact law of docs/method.md §1 (Signorini and
// implicit Coulomb at every node and instant). Every measure is relative and dimensionless, so one
// threshold serves all scenes: a solution exact to round-off gives ~1e-15, a LATIN iterate at
// indicator η gives roughly η.
#include "stcontact/problem/problem.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc {

/// Largest violation over all nodes i and instants k, with the scales
///   V = max_{i,k} |v|  (displacements, both directions),  Λ = max_{i,k} |λ_n|,  G = max_{i,k} g,
/// the gap g = g0 + v_n and the slip increment s = v_t(t_k) − v_t(t_{k−1}) (v_t(t_{−1}) = 0); in 3D
/// λ_t and s are vectors of the tangent plane and |·| their Euclidean norms.
/// A ratio whose scale is zero counts as 0 if its numerator is 0, +∞ otherwise.
struct ContactLawViolation {
  double penetration = 0.0;        ///< max(−g, 0) / V                         (g ≥ 0)
  double negative_pressure = 0.0;  ///< max(−λ_n, 0) / Λ                       (λ_n ≥ 0)
  double complementarity = 0.0;    ///< |g λ_n| / (G Λ)                        (g λ_n = 0)
  double cone = 0.0;               ///< max(|λ_t| − μ λ_n, 0) / Λ              (|λ_t| ≤ μ λ_n)
  /// Stick: strictly inside the cone the node does not slip. Measured as the smaller of the two
  /// relative quantities that cannot both be nonzero, min(|s| / V, max(μ λ_n − |λ_t|, 0) / Λ), so
  /// that a node on the cone to round-off is not mistaken for a sticking one.
  double stick_slip = 0.0;
  /// (|λ_t| |s| + λ_t·s) / (2 Λ V), zero when λ_t opposes s (in 2D: max(λ_t s, 0) / (Λ V)).
  double slip_direction = 0.0;

  double max() const;
};

/// Checks `history` (v and λ, d n_C × m) against the law with the problem's g0 and μ.
ContactLawViolation checkContactLaw(const Problem& problem, const InterfaceHistory& history);

}  // namespace stc
