#pragma once
// The runs of `stcontact scaling` (docs/scaling.md): at each size of the study, the comparison of
// `stcontact compare` (compare_runs.hpp) with every iterative run stopped at the target true error,
// then every strategy solved as a user runs it, at the target as tolerance (measureAtTolerance).
// The program plans the sizes from its options; this measures one.
#include <string>
#include <vector>

#include "stcontact/options/strategy.hpp"
#include "stcontact/scene/scene.hpp"
#include "stcontact/studies/compare_runs.hpp"
#include "stcontact/studies/progress.hpp"
#include "stcontact/studies/scaling_study.hpp"

namespace stc {

/// One size of a scaling study: the generator's size parameter and the instants, and the series it
/// belongs to (a size in both runs once).
struct ScalingSize {
  int mesh_size = 0, steps = 0;
  bool in_mesh = false, in_time = false;
};

/// Builds `scene`'s problem (the size's) and its reference, then measures every strategy of
/// study.solvers on it, each iterative run stopped as `stop` says; `progress` shows the runs and notes
/// one line per strategy (none: nothing shown).
ScalingPoint measureScalingSize(const Scene& scene, const ScalingSize& size, const ScalingStudy& study,
                                const EarlyStop& stop, ProgressReporter* progress);

}  // namespace stc
