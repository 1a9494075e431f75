#include "stcontact/fas/fas_options.hpp"

#include <cmath>

#include "stcontact/core/option_check.hpp"

namespace stc::fas {

void FasOptions::validate() const {
  constexpr const char* kOwner = "FAS";
  requireOption(tolerance > 0.0 && std::isfinite(tolerance), kOwner, "tolerance", tolerance, "must be > 0");
  requireOption(max_relaxations >= 1, kOwner, "max_relaxations", max_relaxations, "must be >= 1");
  requireOption(pre_relaxations >= 1, kOwner, "pre_relaxations", pre_relaxations,
                "must be >= 1 (the coarse step needs a global stage)");
  requireOption(post_relaxations >= 0, kOwner, "post_relaxations", post_relaxations, "must be >= 0");
  requireOption(coarse_iterations >= 1, kOwner, "coarse_iterations", coarse_iterations, "must be >= 1");
  requireOption(coarse_anderson >= 0, kOwner, "coarse_anderson", coarse_anderson, "must be >= 0");
  if (safeguard_growth)
    requireOption(*safeguard_growth >= 1.0 && std::isfinite(*safeguard_growth), kOwner, "safeguard_growth",
                  *safeguard_growth, "must be >= 1");
  requireOption(max_skip >= 1, kOwner, "max_skip", max_skip, "must be >= 1");
  requireOption(stagnation_window >= 0, kOwner, "stagnation_window", stagnation_window, "must be >= 0");
}

}  // namespace stc::fas
