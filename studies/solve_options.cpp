#include "stcontact/studies/solve_options.hpp"

#include <iomanip>
#include <sstream>

#include "stcontact/core/input_error.hpp"
#include "stcontact/options/strategy.hpp"

namespace stc {

std::vector<std::string> withSolverOptions(std::vector<std::string> overrides, const std::optional<std::string>& solver,
                                           const std::optional<double>& tolerance,
                                           const std::optional<int>& max_iterations) {
  if (solver) {
    strategyNamed(*solver);  // InputError for an unknown name
    overrides.push_back("solver.name=" + *solver);
  }
  if (tolerance) {
    if (!(*tolerance > 0.0)) throw InputError("--tol must be > 0");
    std::ostringstream value;
    value << std::setprecision(17) << *tolerance;
    overrides.push_back("solver.tolerance=" + value.str());
  }
  if (max_iterations) {
    if (*max_iterations < 1) throw InputError("--max-iterations must be >= 1");
    overrides.push_back("solver.max_iterations=" + std::to_string(*max_iterations));
  }
  return overrides;
}

}  // namespace stc
