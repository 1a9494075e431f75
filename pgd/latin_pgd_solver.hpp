#pragma once
// `latin-pgd`: LATIN (docs/method.md §2) whose global stage is solved in separated form with its
// error controlled (docs/method.md §5; pgd/controlled_global_stage.hpp): an iteration costs a few
// products on the interface and a sparse solve per new direction, not m sparse solves, and the
// iteration converges to the fixed point of the exact global stage.
// History: rank = number of interface directions, sparse_solves = solves so far.
#include "stcontact/options/latin_pgd_options.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_inputs.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::pgd {

/// Solves from inputs.start (s = 0 when none) with the directions begun from inputs.basis_seed (a
/// warm start; may have no column); returns the interface directions, and the spatial modes when
/// inputs.spatial_modes.
SolveResult solveLatinPgd(const Problem& problem, const LatinPgdOptions& options, const SolveInputs& inputs = {});

}  // namespace stc::pgd
