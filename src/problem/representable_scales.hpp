#pragma once
// The magnitudes a scene derives — instants, stiffness, forces of the prescribed displacements and
// loads, initial gaps — must be representable in double precision with room for their squares:
// energies uᵀ K u, the norms ‖λ‖ and the error indicator (docs/method.md §2) square forces,
// stresses and displacements, and a double holds magnitudes in [2.2e-308, 1.8e308] only. So each
// scale s must satisfy 1e-150 ≤ s ≤ 1e150 (s² stays a normal double), and instants must be finite
// and strictly increasing. Outside, a solve writes NaN or Inf into its outputs or never starts (a
// Young's modulus of 1e308 gives an infinite K, one of 1e-308 a K that rounds to zero), so the
// scene is refused before anything is written, the message naming the key and asking for other
// units (e.g. MPa and mm instead of Pa and m).
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/model_spec.hpp"

namespace stc {

/// Largest and smallest scale a derived magnitude may have (its square stays a normal double).
inline constexpr double kLargestScale = 1e150;
inline constexpr double kSmallestScale = 1e-150;

/// Throws InputError (its message starting with the key concerned: "time.end", "material.young",
/// "dirichlet[j].values", "load[j].values", "obstacle.point") when an instant is not finite or not
/// increasing, when the stiffness's largest entry leaves [kSmallestScale, kLargestScale], or when a
/// prescribed displacement, the force it or a load applies, or the force of the initial gaps
/// (max |K| · max |g0|) exceeds kLargestScale (they may be zero). `problem` is built from `scene`,
/// its loads in the scene's order: the [[dirichlet]] entries, then the [[load]] entries.
void requireRepresentableScales(const ModelSpec& scene, const Problem& problem);

}  // namespace stc
