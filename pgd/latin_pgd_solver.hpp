#pragma once
// `latin-pgd`: LATIN (docs/method.md §2) whose global stage is solved in separated form with its
// error controlled (docs/method.md §5; pgd/controlled_global_stage.hpp): an iteration costs a few
// products on the interface and a sparse solve per new direction, not m sparse solves, and the
// iteration converges to the fixed point of the exact global stage.
// History: rank = number of interface directions, sparse_solves = solves so far.
#include "stcontact/incremental/error_reference.hpp"
#include "stcontact/pgd/latin_pgd_options.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::pgd {

/// Solves from `start` (2n_C × m; s = 0 when null) with the directions begun from `seed`
/// (2n_C × p, e.g. a neighbouring problem's SolveResult::interface_directions: a warm start; may
/// have no column).
SolveResult solveLatinPgd(const Problem& problem, const LatinPgdOptions& options,
                          const InterfaceHistory* start = nullptr, const Eigen::MatrixXd* seed = nullptr,
                          const ErrorReference* reference = nullptr, const IterationCallback& callback = {});

}  // namespace stc::pgd
