#pragma once
// The sparse operators of one run, each prepared (factorised) once and shared by whoever needs it:
// the incremental reference, the true-error measure, the strategy and the writer
// (docs/architecture.md, "Operators"). Two kinds:
//   K_ff              the free-dof stiffness: u(λ) = K_ff⁻¹ (f + Bᵀ λ) (displacement.hpp), the
//                     incremental solver's condensed interface, the true error's Delassus columns;
//   K_ff + Bᵀ k B     LATIN's global-stage operator (docs/method.md §2) of one contact interface
//                     (B, k): the whole one, or the part a strategy solves on (a contact zone).
// A run makes one PreparedOperators (stcontact solve, a Python solve) and passes it through
// SolveInputs::operators and to the writer; a solve given none makes its own, so that its
// operators are still prepared once within it. What is prepared is kept until the owner goes:
// preparations() lists it, with the size of each factor. Which backend prepares them (CHOLMOD, or
// PETSc's MUMPS or CG + GAMG) is the owner's LinearSolverOptions (src/linalg/spd_solver.hpp).
#include <Eigen/SparseCore>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "stcontact/linalg/backends/cholmod_factor.hpp"
#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/options/linear_solver_options.hpp"
#include "stcontact/problem/problem.hpp"

namespace stc {

/// One operator prepared in a run, as summary.json lists it ("preparations").
struct Preparation {
  std::string name;              ///< "K_ff", or "K_ff + B^T k B"
  std::string backend;           ///< SpdSolver::backend(): "cholmod", "mumps", "cg-gamg"
  int rows = 0;                  ///< its size
  int contact_nodes = 0;         ///< K_ff + Bᵀ k B: the nodes of its interface (0 for K_ff)
  double factor_nonzeros = 0.0;  ///< entries of its Cholesky factor (SpdSolver::factorNonZeros)
  double seconds = 0.0;          ///< the preparation's wall time
  int uses = 0;                  ///< how many times it was handed out
  bool iterative = false;        ///< a Krylov backend (SpdSolver::isDirect false): its counts below
  KrylovCounts krylov;           ///< its Krylov solves so far (zero for a direct one)
};

/// How a factor orders the dofs its caller condenses on (CholmodFactor's trailing constructor): the
/// dofs `trailing` last when |trailing| · lnz ≥ `min_work` and the dense block fits; with none,
/// CHOLMOD's fill-reducing order alone.
struct Ordering {
  std::vector<int> trailing;
  double min_work = CholmodFactor::kTrailingWork;
  bool operator==(const Ordering&) const = default;
};

/// K_ff + Bᵀ k B of `problem`'s interface (k = contact.search_direction): docs/method.md §2.
Eigen::SparseMatrix<double> searchDirectionOperator(const Problem& problem);

/// A prepared K_ff + Bᵀ k B: the matrix (the FAS coarse space projects it) and its solver.
struct SearchOperator {
  Eigen::SparseMatrix<double> matrix;
  std::unique_ptr<const SpdSolver> factor;
};

class PreparedOperators {
 public:
  /// Operators prepared by `linear`'s backend (an iterative one to linear.rtol, which the front
  /// ends set from the strategy's tolerance: LinearSolverOptions::residualTolerance).
  explicit PreparedOperators(LinearSolverOptions linear = {});
  PreparedOperators(const PreparedOperators&) = delete;
  PreparedOperators& operator=(const PreparedOperators&) = delete;

  /// The factor of problem.stiffness_free, prepared with `ordering` on the first call; every later
  /// call, whatever ordering it asks, gets that same factor (a caller that condenses checks
  /// SpdSolver::condenses and has its fallback). Throws std::invalid_argument for a K_ff other
  /// than the one prepared (one owner serves one body).
  std::shared_ptr<const SpdSolver> stiffnessFree(const Problem& problem, const Ordering& ordering = {});
  /// K_ff + Bᵀ k B of problem.contact with `ordering`: prepared once per distinct operator (the
  /// matrix, compared entry by entry) and ordering.
  std::shared_ptr<const SearchOperator> searchOperator(const Problem& problem, const Ordering& ordering = {});

  /// Every operator prepared so far, in the order prepared.
  std::vector<Preparation> preparations() const;
  /// The Krylov iterations of every operator prepared so far (0 when all are direct).
  long long krylovIterations() const;
  const LinearSolverOptions& linear() const { return linear_; }

 private:
  struct Search {
    Ordering ordering;
    std::shared_ptr<const SearchOperator> op;
    std::size_t record;  ///< its place in records_
  };

  LinearSolverOptions linear_;
  mutable std::mutex mutex_;
  std::vector<Preparation> records_;
  std::shared_ptr<const SpdSolver> stiffness_free_;
  std::uint64_t stiffness_fingerprint_ = 0;
  std::size_t stiffness_record_ = 0;
  std::vector<Search> search_;
};

/// `operators` when given, else `own`, made on first use: the owner a solve prepares with.
PreparedOperators& operatorsOr(PreparedOperators* operators, std::unique_ptr<PreparedOperators>& own);

}  // namespace stc
