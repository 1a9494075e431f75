#pragma once
// Options of the two-level FAS with LATIN as smoother (docs/method.md §4; seed paper §4.1–4.2), the
// cycle both `fas-aposteriori` and `fas-apriori` run. The coarse space's own options belong to each
// strategy's basis (fas_aposteriori_options.hpp, fas_apriori_options.hpp).
#include <optional>

#include "stcontact/options/option_fields.hpp"
#include "stcontact/options/stopping_options.hpp"

namespace stc::fas {

/// How the coarse step starts from s̃ = (ũ, λ̃) (docs/method.md §4, "How the coarse step starts").
enum class CoarseStart {
  ZeroCorrection,     ///< (a) Δv̂ = 0, Δλ̂ = 0, taking v = Bũ (discards v̂ − Bũ)
  InterfaceMismatch,  ///< (b) Δv̂ = v̂ − Bũ, Δλ̂ = 0 (exact when the coarse space is the whole space)
};
inline constexpr std::array<std::pair<std::string_view, CoarseStart>, 2> kCoarseStarts = {{
    {"zero", CoarseStart::ZeroCorrection},
    {"mismatch", CoarseStart::InterfaceMismatch},
}};

/// θ of the safeguard when FasOptions::safeguard_growth is unset: it depends on the dimension and on
/// the coarse space (docs/method.md §4). On the plane meshes corrections that raise the indicator up
/// to 1.8 times often cut the true error, and those from fas-apriori's anticipated expansion up to 15
/// times (hard case ν = 0.49): θ = 1.5, and 5 for the anticipated expansion; on the 3D hemisphere
/// the ones that raise it raise the error too: θ = 1. `anticipated`: the coarse space comes from the
/// anticipated expansion (BasisProvider::anticipates).
constexpr double defaultSafeguardGrowth(int dimension, bool anticipated) {
  if (dimension == 3) return 1.0;
  return anticipated ? 5.0 : 1.5;
}

/// i_C when FasOptions::coarse_iterations is unset: 8 on the plane meshes (fewer lose on the stiff
/// and fine 2D cases: i_C = 4 took 60 relaxations against 37 on the hard case ν = 0.49 and 50
/// against 42 at 801 arc nodes, docs/method.md §4); 4 in 3D, where the coarse step's later
/// iterations overshoot (relaxations to 1e-6 on the generator's hemisphere at divisions 8 / 12 /
/// 16: 18 / 25 / 28 against 20 / 27 / 31; on the graded half-ball 29 against 32; 0.85 to 0.96 of
/// the iterations' time, 1.04 at divisions 12 to 1e-4: docs/floor.md, "Fewer coarse iterations in
/// 3D").
constexpr int defaultCoarseIterations(int dimension) { return dimension == 3 ? 4 : 8; }

struct FasOptions {
  /// Tolerance and cap count fine relaxations (the cost unit of the seed's Figs. 4–5).
  StoppingOptions stop;
  /// ν1: relaxations before the coarse step. The seed's §4.2 uses ν1 = ν2 = 1, and ν = 1 beat ν = 2
  /// for both bases on the seed scene (docs/fas_aposteriori.md, docs/compare_bases.md).
  int pre_relaxations = 1;
  int post_relaxations = 1;  ///< ν2: relaxations after it
  /// i_C: coarse linear stage + fine local stage pairs (seed: 15); unset: defaultCoarseIterations
  /// (dimension). With Anderson depth 2, 8 gave the same or fewer relaxations than the seed's 15 on
  /// the seed scene and every 2D hard case, at about half the coarse work (docs/method.md §4,
  /// docs/floor.md).
  std::optional<int> coarse_iterations;
  /// i_C in force in `dimension`: coarse_iterations, or defaultCoarseIterations(dimension) unset.
  int coarseIterationsIn(int dimension) const {
    return coarse_iterations.value_or(defaultCoarseIterations(dimension));
  }
  /// Anderson depth of the coarse iterations (fas/coarse_step.hpp; 0: plain restricted LATIN).
  int coarse_anderson = 2;
  /// The coarse step on its contact zone only, the open nodes clear of the obstacle eliminated
  /// exactly (fas/coarse_zone.hpp; docs/method.md §4); false: on every node, as the seed.
  bool coarse_zone = true;
  CoarseStart start = CoarseStart::ZeroCorrection;
  /// Safeguard: a coarse correction after which the next relaxation's indicator exceeds
  /// `safeguard_growth` times the one before the coarse step is rejected (the pre-coarse local stage
  /// is restored) and the next coarse steps are skipped for 1, 2, 4, … up to max_skip cycles while
  /// rejections repeat. Without it a poor coarse space (e.g. 10 modes + 5 residual vectors on the
  /// seed scene) can lock FAS in a 2-cycle at true error 0.1-0.2 (docs/fas_aposteriori.md). Off: the
  /// seed's plain cycle.
  bool safeguard = true;
  /// θ ≥ 1 of the safeguard; unset: defaultSafeguardGrowth(dimension, the provider anticipates). The
  /// indicator is an imperfect judge of one correction: on the 801-node seed mesh corrections that
  /// cut the true error up to 7 times raised it up to 1.8 times; on the 2D hard case ν = 0.49,
  /// corrections from the anticipated expansion that raised it 3 to 15 times cut the true error by
  /// half; of θ = 1.5, 3, 5, θ = 5 needs the fewest relaxations on every 2D hard case with
  /// fas-apriori (κ = 0.01: 1734, the cap of 2000, 1208; ν = 0.49 to true error 1e-6: 68, 34, 34),
  /// while it costs fas-aposteriori relaxations (friction 2: 63 at θ = 1.5, 132 and 314 at θ = 5 on
  /// two machines); on the 3D hemisphere the corrections that raised it raised the error too
  /// (θ = 1.5 costs 3 to 12 relaxations there). A kept correction that raised it must pay back
  /// within its cycle, or the next one is judged with θ = 1 (fas_solver.cpp; docs/method.md §4,
  /// docs/strategies_3d.md).
  std::optional<double> safeguard_growth;
  int max_skip = 8;  ///< the longest run of skipped coarse steps
  /// With the safeguard, i_C follows its verdicts (additive increase, multiplicative decrease): a
  /// rejected correction halves the coarse iterations of the next coarse steps (at least 1), each
  /// accepted one adds one back, up to i_C. Where the later coarse iterations
  /// overshoot (the 3D hemisphere: 6 of 27 corrections of 15 iterations rejected, none of 4), this
  /// keeps the part that helps; where none is rejected (the plane seed scene) nothing changes.
  /// docs/method.md §4. Off: i_C fixed.
  bool adapt_coarse_iterations = true;
  /// s of the error estimate FAS stops on: the indicator calibrated on earlier iterates
  /// (src/solver/calibrated_estimate.hpp). A cycle changes its own map (the coarse space follows the
  /// iterate), which breaks the extrapolation LATIN stops on; docs/method.md §2 gives the measured
  /// ratios of estimate to true error.
  double estimate_safety = 2.5;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    StoppingOptions::fields(o.stop, visit);
    visit("pre_relaxations", o.pre_relaxations, atLeast(1));
    visit("post_relaxations", o.post_relaxations, atLeast(0));
    visit("coarse_iterations", o.coarse_iterations, atLeast(1));
    visit("coarse_anderson", o.coarse_anderson, atLeast(0));
    visit("coarse_zone", o.coarse_zone, anyFlag());
    visit("coarse_start", o.start, Keywords<CoarseStart>(kCoarseStarts));
    visit("safeguard", o.safeguard, anyFlag(), Exposure::Library);
    visit("safeguard_growth", o.safeguard_growth, atLeast(1));
    visit("max_skip", o.max_skip, atLeast(1), Exposure::Library);
    visit("adapt_coarse_iterations", o.adapt_coarse_iterations, anyFlag());
    visit("estimate_safety", o.estimate_safety, atLeast(1), Exposure::Library);
  }
  void validate() const { validateFields(*this, "FAS"); }
};

}  // namespace stc::fas
