#pragma once
// `fas-aposteriori` (docs/method.md §4; seed paper §4.2–4.3): the two-level FAS on the exact global
// stage, its coarse space the leading SVD modes of a converged solution (aposteriori_basis.hpp) and
// residual vectors renewed every cycle. The yardstick of the a priori basis: it needs the solution
// first.
#include "stcontact/options/fas_aposteriori_options.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_inputs.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::fas {

/// Solves from inputs.start (s = 0 when none), the modes taken from inputs.converged_lambda, or from
/// an incremental solve when it is absent (its cost is not in the summary's wall time).
SolveResult solveFasAposteriori(const Problem& problem, const FasAposterioriOptions& options,
                                const SolveInputs& inputs = {});

}  // namespace stc::fas
