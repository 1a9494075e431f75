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

/// What `auto` weighs (docs/linear_solvers.md, "The crossover"): a direct factor is 18 to 39 times
/// faster per right-hand side than CG + GAMG from 7k to 335k dofs and a space-time solve needs
/// hundreds, so CHOLMOD wherever its factor fits in the memory available (kFactorMemoryShare of
/// it, the factor's estimate from its symbolic analysis), else CG + GAMG (with PETSc); on several
/// ranks MUMPS, the direct factor that runs on them (2.7 times CG + GAMG's speed on 2 ranks at 52k
/// dofs, and CHOLMOD runs in one process only). Without PETSc: CHOLMOD.
struct BackendChoice {
  double factor_bytes = 0.0;     ///< CHOLMOD's estimated factor (CholmodFactor::estimatedBytes)
  double available_bytes = 0.0;  ///< the memory available (availableMemoryBytes)
  int ranks = 1;
  bool petsc = false;            ///< whether the PETSc backends are built
  static constexpr double kFactorMemoryShare = 0.5;
};
LinearBackend chooseLinearBackend(const BackendChoice& choice);

/// A prepared by options.backend (`auto`: chooseLinearBackend for A), which must be built
/// (LinearSolverOptions::validate). An
/// iterative backend stops at options.rtol (set: residualTolerance). Throws InputError naming `what`
/// when A is not positive definite (a direct backend sees it; an iterative one when its solves
/// fail).
std::unique_ptr<SpdSolver> prepareSpdSolver(const Eigen::SparseMatrix<double>& A, const std::string& what,
                                            const LinearSolverOptions& options, const SpdSolverHints& hints);

}  // namespace stc
