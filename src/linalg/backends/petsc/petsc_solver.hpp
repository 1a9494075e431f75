#pragma once
// The PETSc backends of the linear-solver seam (src/linalg/spd_solver.hpp), built when PETSc is
// found (cmake/StcDependencies.cmake):
//   mumps     MUMPS's Cholesky factor (MatGetFactor; symmetric, SYM = 2, so that a negative pivot is
//             counted, INFOG(12), and refused), analysed first so that a factor beyond its memory
//             bound is refused before the numerical work (INFOG(16)); blocks of right-hand sides
//             through MatMatSolve;
//   cg-gamg   KSPCG on the unpreconditioned residual, PCGAMG with the near-null space given (the
//             rigid-body motions), set up once and reused for every right-hand side; each column
//             stops at ‖b − A x‖ ≤ rtol ‖b‖ (LinearSolverOptions), a column that does not is a
//             LinearSolveFailure; dofs held at given values (solveHeld, the incremental solver's
//             whole-body form) by a copy of A with their rows and columns zeroed, solved by CG from
//             the caller's start with the same hierarchy.
// PETSc is initialised on first use (reading the environment's PETSC_OPTIONS, the experts'
// pass-through, with the prefix "stc_" for these solvers: PETSC_OPTIONS="-stc_ksp_monitor") and
// finalised at exit. One process: PETSC_COMM_SELF. Several ranks (src/linalg/ranks.hpp): the
// operator's rows split in contiguous blocks over PETSC_COMM_WORLD, every rank passing the whole
// right-hand sides and receiving the whole solutions (MPI_Allgatherv). cg-gamg with
// LinearSolverOptions::groups = g > 1: the ranks in g groups (MPI_Comm_split), each with its own copy
// of A and of its hierarchy, a block of columns split among them (single columns on every rank
// together), each group's columns then on every rank. A solve holds the solver's lock (PETSc objects
// are not thread-safe).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <vector>
#include <string>

#include "stcontact/linalg/ranks.hpp"
#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/options/linear_solver_options.hpp"

namespace stc {

/// A prepared by PETSc: options.backend is Mumps or CgGamg (which forms the near-null space, when
/// given, as GAMG's coarse basis). Throws InputError naming `what` when MUMPS finds A singular or
/// not positive definite, and FactorTooLarge when MUMPS's analysis estimates more than
/// `max_factor_bytes` on a rank for its factorisation (INFOG(16)), before any numerical work.
std::unique_ptr<SpdSolver> preparePetscSolver(const Eigen::SparseMatrix<double>& A, const std::string& what,
                                              const LinearSolverOptions& options,
                                              const std::function<Eigen::MatrixXd()>& near_null_space,
                                              double max_factor_bytes = 1e300);

/// PETSc (and MPI) started, and this process's place in PETSC_COMM_WORLD.
Ranks petscRanks();

/// `value` of every rank of PETSC_COMM_WORLD, in rank order, on every rank (MPI_Allgather): a
/// collective call.
std::vector<double> petscAllGather(double value);

}  // namespace stc
