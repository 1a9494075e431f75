#include "fas/fas_options.hpp"

#include <cmath>
#include <string>

#include "src/core/input_error.hpp"

namespace stc::fas {
namespace {
void require(bool ok, const char* field, double value, const char* rule) {
  if (!ok) throw InputError(std::string("FAS option ") + field + " = " + std::to_string(value) + ": " + rule);
}
}  // namespace

void FasOptions::validate() const {
  require(tolerance > 0.0 && std::isfinite(tolerance), "tolerance", tolerance, "must be > 0");
  require(max_relaxations >= 1, "max_relaxations", max_relaxations, "must be >= 1");
  require(pre_relaxations >= 1, "pre_relaxations", pre_relaxations, "must be >= 1 (the coarse step needs a global stage)");
  require(post_relaxations >= 0, "post_relaxations", post_relaxations, "must be >= 0");
  require(coarse_iterations >= 1, "coarse_iterations", coarse_iterations, "must be >= 1");
  require(max_skip >= 1, "max_skip", max_skip, "must be >= 1");
  require(stagnation_window >= 0, "stagnation_window", stagnation_window, "must be >= 0");
}

}  // namespace stc::fas
