#pragma once
// A warm start: a solve that begins from a neighbouring problem's solution (the previous value of a
// parameter sweep) instead of s = 0. Whatever parameter changed, any interface history of the right
// size is a valid LATIN start: the solution is the iteration's fixed point (s = ŝ, docs/method.md §2),
// which does not depend on where the iteration began, only the path to it does; and any set of
// interface directions is a valid start for a separated global stage (they are re-orthonormalised
// and their responses solved in the new problem, whose fine level alone decides convergence,
// docs/method.md §5). Only the sizes must match: a change of mesh or time grid (n_C, m) leaves
// nothing to reuse.
#include <Eigen/Core>
#include <string>

#include "stcontact/problem/problem.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc {

/// True when v and λ are both d n_C × m of `problem`.
bool fitsProblem(const InterfaceHistory& history, const Problem& problem);
/// True when the interface directions have d n_C rows (pgd/response_basis.hpp).
bool fitsProblem(const Eigen::MatrixXd& directions, const Problem& problem);

/// Throw std::invalid_argument naming both sizes when the start does not fit, or the first value
/// that is not finite (a caller's error: NaN would reach every output and pass for a solution).
void requireFits(const InterfaceHistory& start, const Problem& problem);
void requireFits(const Eigen::MatrixXd& directions, const Problem& problem);
/// Throws std::invalid_argument "<what> holds <value> at row r, column k: ..." for the first entry
/// of `values` that is not finite.
void requireFinite(const Eigen::MatrixXd& values, const std::string& what);

}  // namespace stc
