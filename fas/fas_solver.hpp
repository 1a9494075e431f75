#pragma once
// Two-level FAS with LATIN as the smoother (seed §4; docs/method.md §4). One cycle:
//   ν1 relaxations (global stage, then local stage) → coarse step (i_C coarse linear + fine local
//   stages in the coarse space of the provider) → ν2 relaxations.
// Convergence is tested on the fine level only, after every relaxation (its global stage).
#include "stcontact/fas/basis_provider.hpp"
#include "stcontact/fas/fas_options.hpp"
#include "stcontact/incremental/error_reference.hpp"
#include "stcontact/latin/linear_stage.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::fas {

/// History: one record per relaxation (iteration = relaxations), rank = coarse-space size.
/// `solver_name` is recorded in the summary ("fas-aposteriori", "fas-apriori"). Starts from s = 0.
SolveResult solveFas(const Problem& problem, latin::LinearStage& global, BasisProvider& provider,
                     const FasOptions& options, const std::string& solver_name,
                     const ErrorMeasure* reference = nullptr, const IterationCallback& callback = {});

/// The same from `start` (2n_C × m), e.g. a neighbouring problem's converged solution (a warm
/// start): the fine level begins with the local stage of `start`, as it does of s = 0 otherwise.
SolveResult solveFas(const Problem& problem, latin::LinearStage& global, BasisProvider& provider,
                     const InterfaceHistory& start, const FasOptions& options, const std::string& solver_name,
                     const ErrorMeasure* reference = nullptr, const IterationCallback& callback = {});

}  // namespace stc::fas
