#pragma once
// `latin-pgd`: LATIN (docs/method.md §2) whose global stage is solved in separated form (docs/method.md §5).
// Every iteration: local stage, then the update of the time functions on the current spatial modes
// (no sparse solve). The global stage is checked — a rank-one enrichment candidate, a few sparse
// solves — when its error may limit convergence: at the start, when η stagnates (η_n > ρ η_{n−1}),
// when η falls below the last measured global-stage error, and before convergence is accepted.
// A candidate whose change of s exceeds γ · max(η, tolerance) (indicator norm) is kept and the
// update redone; so an iteration costs a handful of sparse solves, not m.
// History: rank = number of modes, sparse_solves = solves so far.
#include "latin/global_stage.hpp"
#include "pgd/latin_pgd_options.hpp"
#include "src/problem/problem.hpp"
#include "src/solver/error_reference.hpp"
#include "src/solver/solve_result.hpp"

namespace stc::pgd {

/// Solves from s = 0. The indicator recorded is max(η, global-stage error estimate) whenever the
/// estimate was measured at that iteration, so convergence needs both below the tolerance.
SolveResult solveLatinPgd(const Problem& problem, const LatinPgdOptions& options,
                          const ErrorReference* reference = nullptr, const IterationCallback& callback = {});

/// The same with a global stage built by the caller (its factor is used; it is not m-solved).
SolveResult solveLatinPgd(const Problem& problem, const latin::GlobalStage& global, const LatinPgdOptions& options,
                          const ErrorReference* reference = nullptr, const IterationCallback& callback = {});

/// A warm start: from `start` (2n_C × m) with the spatial modes begun from `seed_modes` (n_free × r,
/// may have no column; e.g. a neighbouring problem's SolveResult::spatial_modes). The global stage
/// is checked at the first iteration as when there is no mode.
SolveResult solveLatinPgd(const Problem& problem, const latin::GlobalStage& global, const InterfaceHistory& start,
                          const Eigen::MatrixXd& seed_modes, const LatinPgdOptions& options,
                          const ErrorReference* reference = nullptr, const IterationCallback& callback = {});

}  // namespace stc::pgd
