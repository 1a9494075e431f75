#include "latin/latin_options.hpp"

#include <cmath>
#include <string>

#include "src/core/input_error.hpp"

namespace stc::latin {
namespace {
void require(bool ok, const char* field, double value, const char* rule) {
  if (!ok) throw InputError(std::string("LATIN option ") + field + " = " + std::to_string(value) + ": " + rule);
}
}  // namespace

void LatinOptions::validate() const {
  require(tolerance > 0.0 && std::isfinite(tolerance), "tolerance", tolerance, "must be > 0");
  require(max_iterations >= 1, "max_iterations", max_iterations, "must be >= 1");
  require(relaxation > 0.0 && relaxation <= 1.0, "relaxation", relaxation, "must be in (0, 1]");
  require(stagnation_window >= 0, "stagnation_window", stagnation_window, "must be >= 0");
  require(block_size >= 1, "block_size", block_size, "must be >= 1");
}

}  // namespace stc::latin
