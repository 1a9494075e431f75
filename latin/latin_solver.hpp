#pragma once
// The LATIN solver over the whole space-time grid (docs/method.md §2; seed paper §2, eq. (1)):
// alternate the local stage (contact law, node-wise) and the global stage (equilibrium, one
// multi-right-hand-side solve with the factorised K + Bᵀ k B) until the indicator η ≤ tolerance.
// Only the interface histories persist between iterations.
#include "latin/global_stage.hpp"
#include "latin/latin_options.hpp"
#include "src/problem/problem.hpp"
#include "src/solver/error_reference.hpp"
#include "src/solver/solve_result.hpp"

namespace stc::latin {

/// Solves from s = 0. `reference`, when given, adds the true error to every history record.
SolveResult solveLatin(const Problem& problem, const LatinOptions& options, const ErrorReference* reference = nullptr,
                       const IterationCallback& callback = {});

/// The same with a global stage built by the caller (reused across solves or by FAS), from `start`
/// (2n_C × m; e.g. a neighbouring problem's solution: a warm start, src/solver/warm_start.hpp).
SolveResult solveLatin(const Problem& problem, GlobalStage& global, const InterfaceHistory& start,
                       const LatinOptions& options, const ErrorReference* reference = nullptr,
                       const IterationCallback& callback = {});

}  // namespace stc::latin
