#pragma once
// The one place a backend of the linear-solver seam is chosen (src/linalg/spd_solver.hpp): the
// operator A prepared by the backend LinearSolverOptions names, with what each backend can use of
// the caller's knowledge of A.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/options/linear_solver_options.hpp"

namespace stc {

/// What a caller knows of A that a backend may use.
struct SpdSolverHints {
  /// Dofs whose condensed operator the caller will ask for (CHOLMOD orders them last when
  /// |trailing| · lnz ≥ min_work: CholmodFactor's trailing constructor).
  std::vector<int> trailing;
  double min_work = 1e8;
  /// A's near-null space, n × k (the rigid-body motions of the free dofs): GAMG's coarse basis,
  /// formed only by a backend that uses it (none: empty).
  std::function<Eigen::MatrixXd()> near_null_space;
};

/// `auto` (docs/linear_solvers.md, "The crossover"): a direct factor is 18 to 39 times faster per
/// right-hand side than CG + GAMG from 7k to 335k dofs and a space-time solve needs hundreds, so
/// the direct factor wherever it fits in kFactorMemoryShare of the memory available to the rank
/// (its analysis says, before any numerical work), else CG + GAMG (with PETSc): CHOLMOD in one
/// process, MUMPS on several ranks (CHOLMOD runs in one process only; MUMPS there is 2.7 times CG +
/// GAMG's speed on 2 ranks at 52k dofs). Without PETSc: CHOLMOD, bounded by all the memory available
/// (there is nothing to give way to: beyond, the run is refused, as for a factor asked for by name).
struct AutoBackend {
  LinearBackend backend;    ///< the backend to prepare with
  double max_factor_bytes;  ///< the direct factor's bound (per rank)
  bool gives_way;           ///< beyond the bound, CG + GAMG prepares instead (else: refused)
};
inline constexpr double kFactorMemoryShare = 0.5;
/// `available_bytes`: what this rank may use (the machine's available memory shared by its ranks).
AutoBackend autoBackend(int ranks, bool petsc, double available_bytes);

/// The error for a direct factor asked for by name (or `auto`'s without PETSc) whose analysis said
/// it would exceed the memory the rank may use (`refused`, FactorTooLarge with that bound): an
/// InputError naming solver.linear and the backend that needs no factor.
InputError factorRefused(LinearBackend backend, const FactorTooLarge& refused);

/// A prepared by options.backend (`auto`: autoBackend), which must be built
/// (LinearSolverOptions::validate). An iterative backend stops at options.rtol (set:
/// residualTolerance). Throws InputError naming `what`
/// when A is not positive definite (a direct backend sees it; an iterative one when its solves
/// fail), and factorRefused's when a direct factor asked for by name would exceed the memory
/// available to the rank.
std::unique_ptr<SpdSolver> prepareSpdSolver(const Eigen::SparseMatrix<double>& A, const std::string& what,
                                            const LinearSolverOptions& options, const SpdSolverHints& hints);

}  // namespace stc
