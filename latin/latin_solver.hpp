#pragma once
// The LATIN solver over the whole space-time grid (docs/method.md §2; seed paper §2, eq. (1)):
// alternate the local stage (contact law, node-wise) and the global stage (equilibrium) until the
// estimate of the true error (src/solver/error_estimate.hpp) is at most the tolerance. Only the
// interface histories persist between iterations. The global stage is exact (latin::GlobalStage:
// one multi-right-hand-side solve with the factorised K + Bᵀ k B, strategy `latin`) or separated
// and controlled (pgd::ControlledGlobalStage, strategy `latin-pgd`).
#include <string>

#include "stcontact/latin/linear_stage.hpp"
#include "stcontact/options/latin_options.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_inputs.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::latin {

/// `latin`: solves from inputs.start (s = 0 when none) with the exact global stage.
SolveResult solveLatin(const Problem& problem, const LatinOptions& options, const SolveInputs& inputs = {});

/// The same iteration with a global stage built by the caller (a separated one, or one reused across
/// solves); `solver_name` is recorded in the summary.
SolveResult solveLatinWith(const Problem& problem, LinearStage& global, const LatinOptions& options,
                           const SolveInputs& inputs, const std::string& solver_name);

}  // namespace stc::latin
