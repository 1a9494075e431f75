#pragma once
// Options of the two-level FAS with LATIN as smoother (docs/method.md §4; seed paper §4.1–4.2).
// Defaults: src/core/solver_settings.hpp. The coarse space's own options (residual vectors, modes)
// belong to its BasisProvider, the block size of the solves to the latin::GlobalStage the caller
// builds.
#include <optional>

#include "stcontact/core/solver_settings.hpp"

namespace stc::fas {

using stc::CoarseStart;

struct FasOptions {
  /// On the error estimate (src/solver/error_estimate.hpp), tested after every relaxation.
  double tolerance = defaults::tolerance;
  /// Fine relaxations in all (the cost unit of the seed's Figs. 4–5).
  int max_relaxations = defaults::max_iterations;
  int pre_relaxations = defaults::pre_relaxations;    ///< ν1 >= 1: the seed's Figs. 4–5 use ν1 = ν2 = 1
  int post_relaxations = defaults::post_relaxations;  ///< ν2 >= 0
  /// i_C: coarse linear stage + fine local stage pairs (seed: 15).
  int coarse_iterations = defaults::coarse_iterations;
  /// Anderson depth of the coarse iterations (fas/coarse_step.hpp; 0: plain restricted LATIN).
  int coarse_anderson = defaults::coarse_anderson;
  /// The coarse step on its contact zone (fas/coarse_zone.hpp); false: on every node, as the seed.
  bool coarse_zone = defaults::coarse_zone;
  CoarseStart start = defaults::coarse_start;
  /// Safeguard: a coarse correction after which the next relaxation's indicator exceeds
  /// `safeguard_growth` times the one before the coarse step is rejected (the pre-coarse local stage is restored) and the next
  /// coarse steps are skipped for 1, 2, 4, … up to max_skip cycles while rejections repeat. Without
  /// it a poor coarse space (e.g. 10 modes + 5 residual vectors on the seed scene) can lock FAS in
  /// a 2-cycle at true error 0.1-0.2 (docs/compare_bases.md). Off: the seed's plain cycle.
  bool safeguard = true;
  /// θ ≥ 1 of the safeguard; unset: defaults::safeguardGrowth(problem.dimension, the provider
  /// anticipates): in 2D 1.5, or 5 for fas-apriori's anticipated expansion; 1 in 3D. The indicator
  /// is an imperfect judge of one correction: on the 801-node seed mesh corrections that cut the
  /// true error up to 7 times raised it up to 1.8 times; on the 2D hard case ν = 0.49,
  /// corrections from the anticipated expansion that raised it 3 to 15 times cut the true error by
  /// half; of θ = 1.5, 3, 5, θ = 5 needs the fewest relaxations on every 2D hard case with
  /// fas-apriori (κ = 0.01: 1734, the cap of 2000, 1208; ν = 0.49 to true error 1e-6: 68, 34, 34),
  /// while it costs fas-aposteriori relaxations (friction 2: 63 at θ = 1.5, 132 and 314 at θ = 5 on
  /// two machines); on the 3D hemisphere the corrections that raised it raised the error too
  /// (θ = 1.5 costs 3 to 12 relaxations there). A kept correction that raised it must pay back
  /// within its cycle, or the next one is judged with θ = 1 (fas_solver.cpp; docs/method.md §4,
  /// docs/three_d.md).
  std::optional<double> safeguard_growth;
  int max_skip = 8;               ///< >= 1, longest run of skipped coarse steps
  /// With the safeguard, i_C follows its verdicts (additive increase, multiplicative decrease): a
  /// rejected correction halves the coarse iterations of the next coarse steps (at least 1), each
  /// accepted one adds one back, up to coarse_iterations. Where the later coarse iterations
  /// overshoot (the 3D hemisphere: 6 of 27 corrections of 15 iterations rejected, none of 4), this
  /// keeps the part that helps; where none is rejected (the plane seed scene) nothing changes.
  /// docs/method.md §4. Off: i_C fixed.
  bool adapt_coarse_iterations = true;
  int stagnation_window = defaults::stagnation_window;  ///< relaxations without a 1% decrease of η (0: never)

  void validate() const;  ///< throws InputError naming the field
};

}  // namespace stc::fas
