#include "stcontact/latin/latin_options.hpp"

#include <cmath>

#include "stcontact/core/option_check.hpp"

namespace stc::latin {

void LatinOptions::validate() const {
  constexpr const char* kOwner = "LATIN";
  requireOption(tolerance > 0.0 && std::isfinite(tolerance), kOwner, "tolerance", tolerance, "must be > 0");
  requireOption(max_iterations >= 1, kOwner, "max_iterations", max_iterations, "must be >= 1");
  requireOption(relaxation > 0.0 && relaxation <= 1.0, kOwner, "relaxation", relaxation, "must be in (0, 1]");
  requireOption(stagnation_window >= 0, kOwner, "stagnation_window", stagnation_window, "must be >= 0");
  requireOption(block_size >= 1, kOwner, "block_size", block_size, "must be >= 1");
}

}  // namespace stc::latin
