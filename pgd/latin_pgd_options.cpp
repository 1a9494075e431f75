#include "pgd/latin_pgd_options.hpp"

#include <cmath>
#include <string>

#include "src/core/input_error.hpp"

namespace stc::pgd {
namespace {
void require(bool ok, const char* field, double value, const char* rule) {
  if (!ok) throw InputError(std::string("latin-pgd option ") + field + " = " + std::to_string(value) + ": " + rule);
}
}  // namespace

void LatinPgdOptions::validate() const {
  require(tolerance > 0.0 && std::isfinite(tolerance), "tolerance", tolerance, "must be > 0");
  require(max_iterations >= 1, "max_iterations", max_iterations, "must be >= 1");
  require(stagnation_window >= 0, "stagnation_window", stagnation_window, "must be >= 0");
  require(max_rank >= 1, "max_rank", max_rank, "must be >= 1");
  require(enrichment_ratio > 0.0 && enrichment_ratio <= 1.0, "enrichment_ratio", enrichment_ratio, "must be in (0, 1]");
  require(stagnation_ratio > 0.0, "stagnation_ratio", stagnation_ratio, "must be > 0");
  require(max_modes_per_iteration >= 1, "max_modes_per_iteration", max_modes_per_iteration, "must be >= 1");
  require(enrichment.max_sweeps >= 1, "enrichment.max_sweeps", enrichment.max_sweeps, "must be >= 1");
}

}  // namespace stc::pgd
