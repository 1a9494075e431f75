#pragma once
// The global (linear) stage as the LATIN and FAS loops see it (docs/method.md §2): from the local
// stage's ŝ, an iterate s ∈ A_d (equilibrium, kinematics). Two kinds:
//   - latin::GlobalStage: exact, m sparse solves with the factorised A = K_ff + Bᵀ k B;
//   - pgd::ControlledGlobalStage: in separated form, exact for the projection of its right-hand
//     sides on known interface directions, enriched until the projection error is below a share
//     of the last iteration's gap ‖s − ŝ‖ (docs/method.md §5).
// Both return an s that is exactly in equilibrium (K_ff u = f + Bᵀ λ): the error estimate and the
// true error of src/solver/ are exact functions of it.
#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc::latin {

class LinearStage {
 public:
  virtual ~LinearStage() = default;
  /// s from ŝ = `hat`, for every instant.
  virtual void solve(const InterfaceHistory& hat, InterfaceHistory& s) = 0;
  /// Tells the stage the gap ‖s − ŝ‖ (indicator norm, docs/method.md §2) of the iterate it just
  /// returned; a controlled stage bounds its next projection error by a share of it.
  virtual void observeGap(double /*gap*/) {}
  /// Right-hand sides solved with the sparse factor so far.
  virtual long sparseSolves() const = 0;
  /// Size of the separated representation (0 for the exact stage).
  virtual int rank() const { return 0; }
  /// Whether the map ŝ ↦ s changes from one iteration to the next (a controlled stage adds
  /// directions), which the error estimate must allow for (latin_solver.cpp).
  virtual bool changesItsMap() const { return false; }
  /// The factor of A = K_ff + Bᵀ k B.
  virtual const SpdSolver& factor() const = 0;
  /// ‖r‖_{k⁻¹} of the last solve: how far its iterate may lie from the exact global stage's (a
  /// controlled stage's projection error; 0 for the exact stage). Both are in equilibrium and differ
  /// by δs with ‖δs‖²_K = Σ δv·δλ ≤ ‖r‖²_{k⁻¹} / 4 (pgd/controlled_global_stage.hpp), which the error
  /// estimate adds (IterationMonitor::record): the iteration's own estimate cannot see it.
  virtual double projectionError() const { return 0.0; }
};

}  // namespace stc::latin
