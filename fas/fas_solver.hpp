#pragma once
// Two-level FAS with LATIN as the smoother (seed §4; docs/method.md §4). One cycle:
//   ν1 relaxations (global stage, then local stage) → coarse step (i_C coarse linear + fine local
//   stages in the coarse space of the provider) → ν2 relaxations.
// Convergence is tested on the fine level only, after every relaxation (its global stage).
#include "stcontact/fas/basis_provider.hpp"
#include "stcontact/latin/linear_stage.hpp"
#include "stcontact/options/fas_options.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_inputs.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::fas {

/// The FAS cycle on `global` with the coarse spaces of `provider`, from inputs.start (s = 0 when none;
/// the fine level begins with the local stage of the start). History: one record per relaxation
/// (iteration = relaxations), rank = coarse-space size. `solver_name` is recorded in the summary
/// ("fas-aposteriori", "fas-apriori"); the strategies build their stage and provider around it
/// (fas/aposteriori/, fas/apriori/).
SolveResult solveFas(const Problem& problem, latin::LinearStage& global, BasisProvider& provider,
                     const FasOptions& options, const SolveInputs& inputs, const std::string& solver_name);

}  // namespace stc::fas
