#pragma once
// The options of a solve given beside its scene (the command line's --solver, --tol and
// --max-iterations; the Python module's solver=, tol= and max_iterations=) as scene overrides, so
// that the scene's recorded parameters say what was solved.
#include <optional>
#include <string>
#include <vector>

namespace stc {

/// `overrides` followed by the solver's name, the tolerance and the iteration cap as overrides, each
/// checked (a known solver, tol > 0, max-iterations >= 1; InputError otherwise).
std::vector<std::string> withSolverOptions(std::vector<std::string> overrides, const std::optional<std::string>& solver,
                                           const std::optional<double>& tolerance,
                                           const std::optional<int>& max_iterations = std::nullopt);

}  // namespace stc
