#pragma once
// The LATIN solver over the whole space-time grid (docs/method.md §2; seed paper §2, eq. (1)):
// alternate the local stage (contact law, node-wise) and the global stage (equilibrium) until the
// estimate of the true error (src/solver/error_estimate.hpp) is at most the tolerance. Only the
// interface histories persist between iterations. The global stage is exact (latin::GlobalStage:
// one multi-right-hand-side solve with the factorised K + Bᵀ k B, strategy `latin`) or separated
// and controlled (pgd::ControlledGlobalStage, strategy `latin-pgd`).
#include <string>

#include "stcontact/incremental/error_reference.hpp"
#include "stcontact/latin/global_stage.hpp"
#include "stcontact/latin/latin_options.hpp"
#include "stcontact/latin/linear_stage.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::latin {

/// Solves from s = 0 with the exact global stage. `reference`, when given, adds the true error to
/// every history record.
SolveResult solveLatin(const Problem& problem, const LatinOptions& options, const ErrorReference* reference = nullptr,
                       const IterationCallback& callback = {});

/// The same with a global stage built by the caller (reused across solves, or a separated one),
/// from `start` (2n_C × m; e.g. a neighbouring problem's solution: a warm start,
/// src/solver/warm_start.hpp). `solver_name` is recorded in the summary.
SolveResult solveLatin(const Problem& problem, LinearStage& global, const InterfaceHistory& start,
                       const LatinOptions& options, const ErrorReference* reference = nullptr,
                       const IterationCallback& callback = {}, const std::string& solver_name = "latin");

}  // namespace stc::latin
