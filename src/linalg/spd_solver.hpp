#pragma once
// The linear-solver seam: a symmetric positive definite operator A prepared once (a factor, or a
// preconditioner), then blocks of right-hand sides solved, X = A⁻¹ B (docs/method.md §2,
// "factorise once, then one multi-right-hand-side solve per iteration"; docs/linear_solvers.md).
// One interface, one file per backend (src/linalg/backends/), one test suite run on every backend
// built (tests/linalg/test_spd_solver.cpp):
//   cholmod   CHOLMOD's sparse Cholesky, the embedded default (cholmod_factor.hpp);
//   mumps     MUMPS's Cholesky through PETSc (built when PETSc is found);
//   cg-gamg   conjugate gradients preconditioned by PETSc's GAMG with the rigid-body near-null
//             space: inexact, to a relative residual (LinearSolverOptions).
// A direct backend may also hand out the condensed operator C A⁻¹ Cᵀ of the dofs its caller named
// when it was prepared (CHOLMOD's trailing block): a capability, asked with condenses(); every
// caller has the fallback of solving with Cᵀ.
// Threads: solve(B, workspace) only reads the prepared operator; what it writes lives in the
// workspace. Whether two threads may solve at once is the backend's (solveInParts decides).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace stc {

/// An iterative solve that did not reach its tolerance (divergence, the iteration cap), naming the
/// backend and its reason: the run ends as a numerical issue, never with a wrong answer.
class LinearSolveFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A direct factor refused before its numerical work because its analysis says it would exceed
/// the memory bound it was given (`auto`'s: src/linalg/prepare_spd_solver.hpp).
class FactorTooLarge : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What the Krylov solves of an iterative backend took so far (zero for a direct one).
struct KrylovCounts {
  long long solves = 0;      ///< right-hand sides solved
  long long iterations = 0;  ///< their iterations in all
  int max_iterations = 0;    ///< the most one right-hand side took
};

class SpdSolver {
 public:
  /// What one thread's solves write; the backend fills it on first use. Not shared between
  /// threads at the same time.
  class Workspace {
   public:
    struct State {
      virtual ~State() = default;
    };
    Workspace();
    ~Workspace();
    Workspace(Workspace&&) noexcept;
    Workspace& operator=(Workspace&&) noexcept;
    std::unique_ptr<State> state;
  };

  SpdSolver();
  virtual ~SpdSolver();
  SpdSolver(const SpdSolver&) = delete;
  SpdSolver& operator=(const SpdSolver&) = delete;

  /// X = A⁻¹ B for every column of B (size() rows), writing into `workspace`. Throws
  /// std::invalid_argument for a B of another row count, LinearSolveFailure when an iterative solve
  /// does not reach its tolerance.
  virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& B, Workspace& workspace) const = 0;
  /// The same with the solver's own workspace: one thread at a time.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// The columns of B in parts of `part` columns, handed out to threads each with workspaces[t]
  /// (added as needed, kept for the next call): the result does not depend on the thread count.
  /// Default: the whole of B on this thread with workspaces[0]. Not from inside a parallelFor body.
  virtual Eigen::MatrixXd solveInParts(const Eigen::MatrixXd& B, int part, std::vector<Workspace>& workspaces) const;
  /// Many columns of one caller (the Delassus operator of the incremental solver) over the threads
  /// where the backend can. Default: solve(B).
  virtual Eigen::MatrixXd solveOnThreads(const Eigen::MatrixXd& B) const;
  /// X = A⁻¹ B with column j's relative residual allowed `loosening[j]` (≥ 1) times the prepared
  /// one, at most LinearSolverOptions::kLoosestRtol: an iterative backend stops there, a direct one
  /// solves exactly (the default: solve(B)).
  /// For right-hand sides whose weight in the result is small (the directions of the separated
  /// stage, pgd/controlled_global_stage.hpp, "Inexact directions"). std::invalid_argument for a
  /// loosening of another size than B's columns or below 1.
  virtual Eigen::MatrixXd solveLoosened(const Eigen::MatrixXd& B, const Eigen::VectorXd& loosening) const;

  /// Whether C A⁻¹ Cᵀ is at hand without solves: every nonzero column of C (r × n) among the dofs
  /// named when A was prepared. Default: never.
  virtual bool condenses(const Eigen::SparseMatrix<double>& C) const;
  /// C A⁻¹ Cᵀ (r × r) for a C that condenses(); std::invalid_argument for another.
  virtual Eigen::MatrixXd condensed(const Eigen::SparseMatrix<double>& C) const;
  /// A⁻¹ Rᵀ U for an R that condenses() (about half a solve per column on CHOLMOD's trailing
  /// block); std::invalid_argument for another.
  virtual Eigen::MatrixXd solveFromTrailing(const Eigen::SparseMatrix<double>& R, const Eigen::MatrixXd& U) const;

  /// Rows of A replaced for one solveHeld (a Newton step's friction rows, which make the operator
  /// nonsymmetric): row dofs[j] of the operator becomes rows.row(j) (size() columns, within the
  /// pattern of A's rows of dofs[j]'s node).
  struct ReplacedRows {
    std::vector<int> dofs;
    Eigen::SparseMatrix<double, Eigen::RowMajor> rows;
  };
  /// Whether solveHeld is at hand: a backend that solves A with some dofs held at given values
  /// without preparing again (cg-gamg: the preconditioner prepared for A, reused). Default: never.
  virtual bool holdsDofs() const;
  /// The x with x_i = x0_i on the dofs of `held` (increasing, no repeats, none of them replaced) and
  /// (A' x)_j = b_j on the others, A' being A with `replaced`'s rows, started from x0 there: the
  /// Dirichlet problem A'_FF x_F = b_F − A'_FH x0_H, warm. An iterative backend stops at a residual of
  /// rtol ‖b‖ (a warm start's relative residual, of the right-hand side with the held values moved
  /// into it): CG, or GMRES when rows are replaced. std::invalid_argument for another backend or
  /// sizes.
  virtual Eigen::VectorXd solveHeld(const Eigen::VectorXd& b, const std::vector<int>& held, const Eigen::VectorXd& x0,
                                    const ReplacedRows& replaced) const;

  virtual int size() const = 0;
  /// The backend's name as solver.linear spells it ("cholmod", "mumps", "cg-gamg").
  virtual std::string backend() const = 0;
  /// Whether a solve is exact to round-off (a direct factor) or to a residual tolerance.
  virtual bool isDirect() const = 0;
  /// Entries of the factor (direct backends), 0 when there is none: about 8 bytes each.
  virtual double factorNonZeros() const = 0;
  /// The Krylov solves so far (iterative backends).
  virtual KrylovCounts krylovCounts() const;

 protected:
  /// solveLoosened's check of its arguments.
  static void checkLoosening(const Eigen::MatrixXd& B, const Eigen::VectorXd& loosening);

 private:
  mutable Workspace own_;  ///< solve(B)'s
};

}  // namespace stc
