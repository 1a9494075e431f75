#pragma once
// The help text of --tol and --max-iterations, with the defaults a scene without those keys gets
// (declared once, src/options/stopping_options.hpp).
#include <string>

#include "stcontact/options/stopping_options.hpp"
#include "stcontact/studies/number_format.hpp"

namespace stc::cli {

inline std::string toleranceHelp() {
  return "tolerance on the error estimate (default: the scene's solver.tolerance, else " +
         shortNumber(StoppingOptions{}.tolerance, 6) + ")";
}

inline std::string maxIterationsHelp() {
  return "iteration limit, FAS: relaxations (default: the scene's solver.max_iterations, else " +
         std::to_string(StoppingOptions{}.max_iterations) + ")";
}

}  // namespace stc::cli
