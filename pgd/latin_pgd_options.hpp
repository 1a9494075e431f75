#pragma once
// Options of `latin-pgd`: LATIN whose global stage is solved in separated form (docs/method.md §5).
#include "pgd/rank_one_enrichment.hpp"
#include "src/core/solver_settings.hpp"

namespace stc::pgd {

struct LatinPgdOptions {
  double tolerance = defaults::tolerance;  ///< on the indicator, once the global-stage error is checked below it
  int max_iterations = defaults::max_iterations;
  int stagnation_window = defaults::stagnation_window;  ///< as LATIN's (0: never)
  int max_rank = 400;           ///< modes at most (the exact global stage needs ≤ q + 2n_C of them)
  /// Enrich while the next mode would move s by more than γ = this times max(η, tolerance) in the
  /// indicator's norm. A global-stage error ε per iteration shifts LATIN's fixed point by about
  /// ε / (1 − ρ), ρ ≈ 0.9–0.97 its rate per iteration, so γ must be of order 1 − ρ: on the seed
  /// scene γ = 0.2 and 0.1 stagnate at true error 1e-2 and 2e-3, γ = 0.03 converges (docs/compare_bases.md).
  double enrichment_ratio = 0.03;
  /// Check the global stage (enrichment candidate, a few sparse solves) when η_n > ratio · η_{n−1}.
  double stagnation_ratio = 0.99;
  int max_modes_per_iteration = 4;
  EnrichmentOptions enrichment;

  void validate() const;  ///< throws InputError naming the field
};

}  // namespace stc::pgd
