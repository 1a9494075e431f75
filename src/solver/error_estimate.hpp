#pragma once
// An estimate of the true error (docs/method.md §2: relative energy error over the time grid) of an
// iterative solver's equilibrated iterates, without the reference solution (derivation:
// docs/method.md §2, "Error estimate").
//   1. Energy products on the interface. Two equilibrated iterates (K_ff u = f + Bᵀλ) differ by
//      δu = K_ff⁻¹ Bᵀ δλ, so ⟨δu, δu'⟩_K = δuᵀ Bᵀ δλ' = Σ_k δv_k · δλ'_k: exact, on the interface.
//   2. The rate. Over a period of p iterations (1 for LATIN, a FAS cycle's relaxations) the
//      differences Δ_n = u_n − u_{n−p} of a linear iteration near its fixed point follow its dominant
//      eigenvalue μ = ρ e^{iθ}: Δ_n ≈ μ Δ_{n−p}, with ρ = ‖Δ_n‖ / ‖Δ_{n−p}‖ and
//      ρ cos θ = ⟨Δ_n, Δ_{n−p}⟩ / ‖Δ_{n−p}‖². The error then is e_n = μ / (1 − μ) · Δ_n, so
//          ‖u_n − u*‖_K ≈ ρ / |1 − μ| · ‖Δ_n‖,   |1 − μ|² = 1 − 2 ρ cos θ + ρ².
//      A monotone approach (θ = 0) gives the familiar ρ / (1 − ρ); an alternating one (θ = π, what
//      LATIN shows on the seed scene) ρ / (1 + ρ), up to 19 times less at ρ = 0.9.
//      The largest factor of the last `window` periods is used, so that a rate that drifts up (an
//      active set still changing) does not make the estimate optimistic, and ρ is taken at least
//      0.1: convergence may slow down after a fast start (error_estimate.cpp).
//   3. The normalisation: ‖u*‖²_K ≈ E(u_n) (src/solver/equilibrium_energy.hpp).
// The estimate is +∞ until `window` rates are known (window + 1 periods), and while the measured
// rate is ≥ 1.
#include <deque>

#include "src/spacetime/interface_history.hpp"

namespace stc {

class ErrorEstimator {
 public:
  /// `period`: iterations per period of the iteration (≥ 1); `window`: periods whose factors are
  /// kept (≥ 1).
  explicit ErrorEstimator(int period = 1, int window = 3);

  /// Records the equilibrated iterate s_n and E(u_n); returns the estimate of its relative error.
  double record(const InterfaceHistory& s, double energy);
  /// ρ of the last period (NaN before it is known).
  double rate() const { return rate_; }

 private:
  int period_, window_;
  std::deque<InterfaceHistory> iterates_;     ///< the last `period` iterates
  std::deque<InterfaceHistory> differences_;  ///< Δ of the last period + 1 records
  std::deque<double> factors_;                ///< ρ / |1 − μ| of the last `window` periods
  double rate_;
};

/// ⟨u_a − u_b, u_c − u_d⟩_K of equilibrated iterates, given the differences (δv, δλ) of both pairs:
/// Σ_k δv_k · δλ'_k.
double energyProduct(const InterfaceHistory& d1, const InterfaceHistory& d2);

}  // namespace stc
