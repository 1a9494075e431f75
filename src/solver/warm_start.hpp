#pragma once
// A warm start: a solve that begins from a neighbouring problem's solution (the previous value of a
// parameter sweep) instead of s = 0. Whatever parameter changed, any interface history of the right
// size is a valid LATIN start: the solution is the iteration's fixed point (s = ŝ, docs/method.md §2),
// which does not depend on where the iteration began, only the path to it does; and any set of
// free-dof vectors is a valid start for a reduced basis (it is re-orthonormalised in the new
// problem's energy product, and the fine level alone decides convergence, docs/method.md §4). Only the
// sizes must match: a change of mesh or time grid (n_free, n_C, m) leaves nothing to reuse.
#include <Eigen/Core>

#include "src/problem/problem.hpp"
#include "src/spacetime/interface_history.hpp"

namespace stc {

/// True when v and λ are both 2n_C × m of `problem`.
bool fitsProblem(const InterfaceHistory& history, const Problem& problem);
/// True when the vectors have one row per free dof of `problem`.
bool fitsProblem(const Eigen::MatrixXd& spatial_modes, const Problem& problem);

/// Throw std::invalid_argument naming both sizes when the start does not fit (a caller's error).
void requireFits(const InterfaceHistory& start, const Problem& problem);
void requireFits(const Eigen::MatrixXd& spatial_modes, const Problem& problem);

}  // namespace stc
