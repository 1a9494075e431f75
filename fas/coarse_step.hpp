#pragma once
// The coarse step of the two-level FAS (seed §4.1, eqs. (3)–(8); docs/method.md §4): i_C iterations
// of LATIN whose global stage is restricted to the coarse space. With s = (Bũ, λ) the last global
// stage's iterate, W(ŝ) = λ̂ + k v̂ and W_s = λ + k Bũ its right-hand side, eqs. (5), (7), (8) with
// R A P = I (Y A-orthonormal) and res̃ = Bᵀ(λ̃ − λ) read
//   1. coarse linear stage: ξ = (BY)ᵀ (W(ŝ) − W_s),  v = Bũ + BY ξ,  λ = W(ŝ) − k v;
//   2. fine local stage: ŝ ← its result (in Γ).
// (The seed's increments Δv̂ = v̂ − Bũ, Δλ̂ = λ̂ − λ̃ give res̃ + Δλ̂ + kΔv̂ = W(ŝ) − W_s.) Start (a)
// takes ŝ = (Bũ, λ̃), start (b) the local stage's own ŝ = (v̂, λ̃). Each iteration is two products
// with B Y (d n_C × r), a pass over the interface fields and a local stage that forms the trial and
// the next state node by node (latin::localStageOfTrial). Its state is
// w = W(ŝ); with FasOptions::coarse_anderson > 0 the next w is the Anderson mixing of the last
// images (src/linalg/anderson.hpp, in the k⁻¹ norm), the last iteration a plain one, so that the
// result is a local-stage iterate (docs/method.md §4, "Anderson mixing of the coarse iterations").
#include "stcontact/contact/contact_interface.hpp"
#include "stcontact/fas/coarse_space.hpp"
#include "stcontact/options/fas_options.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc::fas {

/// `s` is the last global-stage iterate (v = Bũ, λ), `hat` the local stage that followed it
/// (v̂, λ̃); on return `hat` holds the coarse-corrected local-stage iterate (in Γ).
void coarseStep(const ContactInterface& contact, const CoarseSpace& space, const FasOptions& options,
                const InterfaceHistory& s, InterfaceHistory& hat);

}  // namespace stc::fas
