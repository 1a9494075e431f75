#pragma once
// An estimate of the true error (docs/method.md §2: relative energy error over the time grid) of an
// iterative solver's equilibrated iterates, without the reference solution (derivation:
// docs/method.md §2, "Error estimate").
//   1. Energy products on the interface. Two equilibrated iterates (K_ff u = f + Bᵀλ) differ by
//      δu = K_ff⁻¹ Bᵀ δλ, so ⟨δu, δu'⟩_K = δuᵀ Bᵀ δλ' = Σ_k δv_k · δλ'_k: exact, on the interface.
//   2. Extrapolation. Near its fixed point the iteration is linear; over a period of p iterations
//      (1 for LATIN, a FAS cycle's relaxations) the iterates x_j = u_{jp} (one per period) approach
//      the limit along a few dominant eigenvectors. Minimal polynomial extrapolation (MPE, Cabay &
//      Jackson 1976; Sidi 2017, "Vector extrapolation methods", ch. 1) of order K from the
//      differences w_j = x_{j+1} − x_j finds the limit s exactly when K modes carry the error:
//      c = argmin ‖w_K + Σ_{j<K} c_j w_j‖, c_K = 1, γ = c / Σc, s = Σ_j γ_j x_j, and the error of
//      the newest iterate is x_{K+1} − s = Σ_i β_i w_i with β_i = Σ_{j≤i} γ_j: its energy norm from
//      the Gram matrix of the w's alone. One mode (K = 1) gives ρ/|1 − μ| ‖w‖ for the eigenvalue
//      μ = ρe^{iθ}; K = 2 also covers a mixture of a monotone and an alternating mode.
//   3. Safety: a factor on that, and at least ρ_min/(1 + ρ_min) ‖w_K‖ (the error is never assumed
//      to shrink by more than 1/ρ_min times over the next period). LATIN: factor 2 on the order-2
//      extrapolation, ρ_min = 0.1. FAS, whose cycles change their own map: factor 2 on the largest
//      ratio of extrapolated error to ‖w_K‖ over the last 3 periods, at order 1, ρ_min = 0.01
//      (docs/method.md §2 gives the measured ratios).
//   4. The normalisation: ‖u*‖²_K ≈ E(u_n) (src/solver/equilibrium_energy.hpp).
// Each phase of the period is its own sequence. The estimate is +∞ until its sequence holds K + 1
// differences (K + 2 periods), while the newest difference is the largest of them, and when the
// extrapolation finds no contraction.
#include <Eigen/Core>
#include <deque>
#include <optional>
#include <vector>

#include "stcontact/spacetime/interface_history.hpp"

namespace stc {

class ErrorEstimator {
 public:
  /// `period`: iterations per period of the iteration (≥ 1); `order`: K of the extrapolation (≥ 1);
  /// `safety`: the factor on the extrapolated error (≥ 1); `window`: periods over which the largest
  /// ratio of extrapolated error to newest difference is taken (≥ 1).
  /// `min_rate`: the smallest contraction per period assumed (the estimate is at least
  /// min_rate / (1 + min_rate) times the newest difference).
  explicit ErrorEstimator(int period = 1, int order = 2, double safety = 2.0, int window = 1,
                          double min_rate = 0.1);

  /// Records the equilibrated iterate s_n and E(u_n); returns the estimate of its relative error.
  /// `unrelaxed_step`: ‖T(s_{n−1}) − s_{n−1}‖_K, the step the iteration's own map T made from the
  /// last iterate, when the iteration relaxes it (s_n = s_{n−1} + ω (T(s_{n−1}) − s_{n−1}), ω < 1);
  /// none: the step is the difference of the iterates itself. Whether the iteration stands at a
  /// fixed point (exactly, or to round-off) is judged on it: a relaxed step of ω = 1e-12 times a
  /// large one is not round-off.
  /// `stage_error`: a bound δ, in energy, on how far s_n lies from the iterate of the exact map (a
  /// controlled global stage's ½ ‖r‖_{k⁻¹}, latin/linear_stage.hpp), which the differences of the
  /// iterates do not show: it is added to the extrapolated error before the safety factor,
  /// safety · (f ‖w‖ + δ) / √E. Without it `latin-pgd` at solver.pgd_gap_share = 0.9 stopped at a
  /// true error 1.4 times its estimate and above the tolerance (docs/reliability.md).
  double record(const InterfaceHistory& s, double energy, std::optional<double> unrelaxed_step = std::nullopt,
                double stage_error = 0.0);
  /// Forgets the iterates and differences: the next records start a new sequence (the phase within
  /// the period is kept).
  void reset();

 private:
  /// The iterates of one phase of the period: x_j = u_{jp + phase}.
  struct Sequence {
    std::optional<InterfaceHistory> last;      ///< the newest x_j
    std::deque<InterfaceHistory> differences;  ///< w_0 … w_K, oldest first
    Eigen::MatrixXd gram;                      ///< ⟨w_i, w_j⟩_K of the differences held
    std::deque<double> factors;                ///< extrapolated error / ‖w_K‖ of the last periods
  };
  /// Appends s to `sequence`; returns its extrapolated error relative to √energy, or +∞.
  double extend(Sequence& sequence, const InterfaceHistory& s, double energy, std::optional<double> unrelaxed,
                double stage_error) const;
  /// ‖x_{K+1} − s‖_K of the extrapolation over the differences held, or +∞.
  double extrapolatedError(const Eigen::MatrixXd& gram) const;

  int period_, order_;
  double safety_;
  int window_;
  double smallest_share_;  ///< min_rate / (1 + min_rate)
  long count_ = 0;                  ///< records so far
  std::vector<Sequence> sequences_;  ///< one per phase of the period
};

/// ⟨u_a − u_b, u_c − u_d⟩_K of equilibrated iterates, given the differences (δv, δλ) of both pairs:
/// Σ_k δv_k · δλ'_k.
double energyProduct(const InterfaceHistory& d1, const InterfaceHistory& d2);
/// ‖u_a − u_b‖²_K of two equilibrated iterates a and b: Σ_k (v_a − v_b)_k · (λ_a − λ_b)_k, without
/// forming the difference.
double energyOfDifference(const InterfaceHistory& a, const InterfaceHistory& b);

}  // namespace stc
