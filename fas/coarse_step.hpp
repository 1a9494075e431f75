#pragma once
// The coarse step of the two-level FAS (seed §4.1, eqs. (3)–(8); docs/method.md §4): i_C iterations of
//   1. coarse linear stage: (R A P) Ξ = R [res̃ + Bᵀ(Δλ̂ + k Δv̂)], Δu = P Ξ, Δλ = Δλ̂ − k (BΔu − Δv̂);
//   2. fine local stage on (Bũ + BΔu, λ̃ + Δλ); (Δv̂, Δλ̂) = its result minus (Bũ, λ̃).
// After a global stage K ũ = f + Bᵀλ, so res̃ = f + Bᵀλ̃ − Kũ = Bᵀ(λ̃ − λ) lives on the interface
// and, with Y A-orthonormal (R A P = I), each iteration is two products with B Y (2n_C × r).
#include <Eigen/Core>

#include "fas/coarse_space.hpp"
#include "fas/fas_options.hpp"
#include "src/contact/contact_interface.hpp"
#include "src/spacetime/interface_history.hpp"

namespace stc::fas {

/// `s` is the last global-stage iterate (v = Bũ, λ), `hat` the local stage that followed it
/// (v̂, λ̃ = λ̂); on return `hat` holds the coarse-corrected local-stage iterate (in Γ) and
/// `xi` (r × m) the coarse coordinates of the displacement correction, Δu = Y ξ.
void coarseStep(const ContactInterface& contact, const CoarseSpace& space, const FasOptions& options,
                const InterfaceHistory& s, InterfaceHistory& hat, Eigen::MatrixXd& xi);

}  // namespace stc::fas
