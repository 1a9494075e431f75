#pragma once
// LATIN local stage (docs/method.md §2; Ladevèze 1999 ch. 4 for the method): from s = (v, λ) ∈ A_d find
// ŝ = (v̂, λ̂) ∈ Γ (Signorini + implicit Coulomb) along the search direction λ̂ − λ = k (v̂ − v).
// Node-wise and exact; marches in time because the slip depends on the previous instant.
#include "stcontact/contact/contact_interface.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc::latin {

/// Writes ŝ into `hat` (resized as needed). For each node i and instant k:
///   λ̂_n = max(0, λ_n − k_n (g0 + v_n));
///   open (λ̂_n = 0):  v̂_n = v_n − λ_n/k_n, λ̂_t = 0, v̂_t = v_t − λ_t/k_t;
///   closed:          v̂_n = −g0, v̂_t = c + P_b(v̂_t(t_{k−1}) − c) with c = v_t − λ_t/k_t,
///                    b = μ λ̂_n / k_t, then λ̂_t = λ_t + k_t (v̂_t − v_t)   (stick or slip).
/// P_b projects on the ball of radius b of the tangent space (an interval in 2D: v̂_t is the
/// clamp of v̂_t(t_{k−1}) to [c − b, c + b]; a disc in 3D: the Coulomb cone's closed form), so that
/// λ̂_t = k_t P_b(·) lies in the cone and the slip v̂_t − v̂_t(t_{k−1}) points against it.
/// v̂_t(t_{−1}) = 0: the body starts unloaded. Nodes are independent: with threadCount() > 1 they
/// are split into contiguous ranges, one per thread (src/core/threads.hpp); the same result.
void localStage(const ContactInterface& contact, const InterfaceHistory& s, InterfaceHistory& hat);

/// The local stage of the FAS coarse step's trial (fas/coarse_step.hpp), s = (v0 + dv, w − k (v0 +
/// dv)), formed node by node instead of stored: writes ŝ into `hat` and w' = λ̂ + k v̂ (the next
/// right-hand side) into `image`, each when not null. Bitwise the same as localStage on the stored
/// trial followed by image = λ̂ + k v̂, in one pass over the fields instead of four.
void localStageOfTrial(const ContactInterface& contact, const Eigen::MatrixXd& v0, const Eigen::MatrixXd& dv,
                       const Eigen::MatrixXd& w, InterfaceHistory* hat, Eigen::MatrixXd* image);

}  // namespace stc::latin
