#pragma once
// Which backend of the linear-solver seam (src/linalg/spd_solver.hpp) prepares and solves the run's
// sparse SPD operators (K_ff and K_ff + Bᵀ k B), and how exactly an iterative one solves
// (docs/linear_solvers.md). Keys of the scene's [solver] table: the engine under every strategy.
// Experts pass further PETSc options through the environment variable PETSC_OPTIONS, which PETSc
// reads itself (e.g. PETSC_OPTIONS="-ksp_monitor -pc_gamg_threshold 0.02").
#include <array>
#include <string_view>
#include <utility>

#include "stcontact/options/option_fields.hpp"

namespace stc {

enum class LinearBackend {
  /// The fastest that fits (autoBackend, src/linalg/prepare_spd_solver.hpp): CHOLMOD where
  /// its factor fits in memory, else CG + GAMG; MUMPS on several ranks. The default.
  Auto,
  /// CHOLMOD's sparse Cholesky (SuiteSparse), in the process.
  Cholmod,
  /// MUMPS's sparse Cholesky through PETSc (built with PETSc).
  Mumps,
  /// Conjugate gradients preconditioned by PETSc's smoothed-aggregation AMG (GAMG) with the
  /// rigid-body modes as its near-null space (built with PETSc): inexact, to linear_rtol.
  CgGamg,
};

inline constexpr std::array<std::pair<std::string_view, LinearBackend>, 4> kLinearBackends = {{
    {"auto", LinearBackend::Auto},
    {"cholmod", LinearBackend::Cholmod},
    {"mumps", LinearBackend::Mumps},
    {"cg-gamg", LinearBackend::CgGamg},
}};

/// The backend's name as solver.linear spells it.
constexpr std::string_view nameOf(LinearBackend backend) { return keywordOf<LinearBackend>(kLinearBackends, backend); }

struct LinearSolverOptions {
  LinearBackend backend = LinearBackend::Auto;
  /// An iterative backend stops each right-hand side at ‖b − A x‖ ≤ rtol ‖b‖. 0: derived from the
  /// strategy's tolerance τ, rtol = kRtolPerTolerance · τ (at least kRtolFloor): docs/method.md §2,
  /// "Inexact linear solves".
  double rtol = 0.0;
  /// Krylov iterations per right-hand side at most; a solve that reaches it ends the run as a
  /// numerical issue naming the backend.
  int max_iterations = 1000;
  /// cg-gamg on P ranks: a block of right-hand sides is split among this many groups of P / groups
  /// ranks, each solving its columns with its own copy of the operator and of its AMG hierarchy
  /// (docs/linear_solvers.md, "Groups of ranks"). 1: every rank solves every column together. Must
  /// divide P (checked when the operator is prepared); without ranks, or on another backend, unused.
  int groups = 1;

  static constexpr double kRtolPerTolerance = 1e-4;
  static constexpr double kRtolFloor = 1e-12;
  /// The loosest relative residual a loosened solve stops at, whatever its loosening
  /// (SpdSolver::solveLoosened): the response's relative error in energy is then at most
  /// √κ(A) · 1e-4 (docs/method.md §2, "Inexact linear solves").
  static constexpr double kLoosestRtol = 1e-4;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    visit("linear", o.backend, Keywords<LinearBackend>(kLinearBackends));
    visit("linear_rtol", o.rtol, offOrInOpenUnit());
    visit("linear_max_iterations", o.max_iterations, atLeast(1));
    visit("linear_groups", o.groups, atLeast(1));
  }
  /// The fields, and mumps or cg-gamg only in a build with PETSc (InputError naming solver.linear).
  void validate() const;
  /// InputError naming solver.linear_groups when its groups do not divide `ranks` (several ranks).
  void requireGroupsDivide(int ranks) const;
  /// The relative residual an iterative solve stops at under a strategy of tolerance τ.
  double residualTolerance(double tolerance) const;
};

/// Whether this build has the PETSc backends.
bool petscBackendsBuilt();

}  // namespace stc
