#pragma once
// The one place a backend of the linear-solver seam is chosen (src/linalg/spd_solver.hpp): the
// operator A prepared by the backend LinearSolverOptions names, with what each backend can use of
// the caller's knowledge of A.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <vector>

#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/options/linear_solver_options.hpp"

namespace stc {

/// What a caller knows of A that a backend may use.
struct SpdSolverHints {
  /// Dofs whose condensed operator the caller will ask for (CHOLMOD orders them last when
  /// |trailing| · lnz ≥ min_work: CholmodFactor's trailing constructor).
  std::vector<int> trailing;
  double min_work = 1e8;
  /// A's near-null space, n × k (the rigid-body motions of the free dofs): GAMG's coarse basis.
  Eigen::MatrixXd near_null_space;
};

/// A prepared by options.backend, which must be built (LinearSolverOptions::validate). An
/// iterative backend stops at options.rtol (set: residualTolerance). Throws InputError naming `what`
/// when A is not positive definite (a direct backend sees it; an iterative one when its solves
/// fail).
std::unique_ptr<SpdSolver> prepareSpdSolver(const Eigen::SparseMatrix<double>& A, const std::string& what,
                                            const LinearSolverOptions& options, const SpdSolverHints& hints);

}  // namespace stc
