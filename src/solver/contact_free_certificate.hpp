#pragma once
// A certificate that an equilibrated iterate s = (v, λ) is the contact-free elastic solution to
// rounding: the solution of a scene whose body never reaches the obstacle (a gap of 100, a motion
// away from it). That solution carries no contact force, and stores no strain energy when the
// prescribed motion is rigid, so the relative energy error the stopping rule estimates
// (docs/method.md §2) is 0/0 there and its estimate follows rounding noise. The certificate needs
// no estimate. With the search direction's norms ‖v‖²_k = Σ k v² and ‖λ‖²_{1/k} = Σ λ²/k over the
// nodes and instants:
//   1. every gap is open at every instant, g = g0 + v_n > 0: the contact law holds with λ = 0;
//   2. the forces are rounding, ‖λ‖_{1/k} ≤ 1e-12 ‖v‖_k. The iterate is equilibrated,
//      K_ff u = f + Bᵀ λ, so it differs from the contact-free solution u0 = K_ff⁻¹ f by K_ff⁻¹ Bᵀ λ,
//      whose energy λᵀ B K_ff⁻¹ Bᵀ λ is at most c ‖λ‖²_{1/k} with c ≈ κ R / L ≤ 100 (the interface's
//      flexibility times k, for a search direction in range: src/problem/problem.cpp), so
//      ‖u − u0‖_K ≤ 10 ‖λ‖_{1/k};
//   3. relative to the iterate's energy E: 10 ‖λ‖_{1/k} ≤ τ √E, the relative error then at most τ;
//      or E is rounding, E ≤ 1e-12 ‖v‖²_k (the solution is a rigid motion, its deformation below
//      1e-6 of its displacement): no relative error exists, and the reason says so.
#include <optional>
#include <string>

#include "stcontact/problem/problem.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc {

/// Whether the interface history is a rigid motion to rounding: energy ≤ 1e-12 ‖v‖²_k.
bool storesNoStrainEnergy(const ContactInterface& contact, const InterfaceHistory& s, double energy);

/// The reason of a converged solve when `s`, of energy `energy` = Σ_k u_kᵀ K u_k, is certified as the
/// contact-free solution within `tolerance` (1–3 above); nothing otherwise.
std::optional<std::string> contactFreeSolution(const ContactInterface& contact, const InterfaceHistory& s,
                                               double energy, double tolerance);

}  // namespace stc
