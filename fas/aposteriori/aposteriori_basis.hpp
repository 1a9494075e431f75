#pragma once
// The a posteriori coarse basis of seed §4.2 (`fas-aposteriori`): the leading spatial modes of the
// energy SVD (docs/method.md §3, pgd/space_time_svd.hpp) of a converged solution of the same scene,
// restricted to the free dofs. Useless in practice (it needs the solution first); it is the
// yardstick the a priori basis is measured against.
#include <Eigen/Core>

#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/problem/problem.hpp"

namespace stc::fas {

/// n_free × count: rows `problem.free_dofs` of the first `count` energy-SVD spatial modes of the
/// full displacement history rebuilt from `converged_lambda` (d n_C × m).
Eigen::MatrixXd aposterioriModes(const Problem& problem, const SpdSolver& stiffness_free,
                                 const Eigen::MatrixXd& converged_lambda, int count);

}  // namespace stc::fas
