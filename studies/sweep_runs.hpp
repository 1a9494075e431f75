#pragma once
// The solves of `stcontact sweep`, value after value: the incremental reference (for the true error),
// the warm solve from the previous value's solution and spatial modes, and the cold solve from zero,
// each through the registry (strategies/registry.hpp) with a problem (and factorisation) built for that value.
#include <filesystem>
#include <optional>
#include <string>

#include "stcontact/scene/scene.hpp"
#include "stcontact/scene/sweep_range.hpp"
#include "stcontact/studies/progress.hpp"
#include "stcontact/studies/sweep.hpp"

namespace stc {

struct SweepSettings {
  Strategy solver = Strategy::FasApriori;
  bool independent = true;                             ///< also solve every value cold
  std::optional<std::filesystem::path> solutions_dir;  ///< write each warm solution below it
  ProgressReporter* progress = nullptr;               ///< shows each solve and each value's line
};

/// What the next value's warm solve starts from: the last warm solution and its spatial modes.
class WarmChain {
 public:
  /// Solves value `index` of `range` (its scene: `scene`) warm and, if asked, cold.
  SweepPoint solveValue(const Scene& scene, const SweepRange& range, std::size_t index, const SweepSettings& settings);

 private:
  std::optional<InterfaceHistory> interface_;
  Eigen::MatrixXd modes_;
};

}  // namespace stc
