#include "pgd/latin_pgd_options.hpp"

#include <cmath>

#include "src/core/option_check.hpp"

namespace stc::pgd {

void LatinPgdOptions::validate() const {
  constexpr const char* kOwner = "latin-pgd";
  requireOption(tolerance > 0.0 && std::isfinite(tolerance), kOwner, "tolerance", tolerance, "must be > 0");
  requireOption(max_iterations >= 1, kOwner, "max_iterations", max_iterations, "must be >= 1");
  requireOption(stagnation_window >= 0, kOwner, "stagnation_window", stagnation_window, "must be >= 0");
  requireOption(max_rank >= 1, kOwner, "max_rank", max_rank, "must be >= 1");
  requireOption(enrichment_ratio > 0.0 && enrichment_ratio <= 1.0, kOwner, "enrichment_ratio", enrichment_ratio,
                "must be in (0, 1]");
  requireOption(stagnation_ratio > 0.0, kOwner, "stagnation_ratio", stagnation_ratio, "must be > 0");
  requireOption(max_modes_per_iteration >= 1, kOwner, "max_modes_per_iteration", max_modes_per_iteration,
                "must be >= 1");
  requireOption(enrichment.max_sweeps >= 1, kOwner, "enrichment.max_sweeps", enrichment.max_sweeps, "must be >= 1");
}

}  // namespace stc::pgd
