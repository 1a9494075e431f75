#pragma once
// The `cholmod` backend of the linear-solver seam (src/linalg/spd_solver.hpp), the embedded
// default: one sparse Cholesky factorisation (CHOLMOD LLᵀ, simplicial or supernodal as CHOLMOD
// chooses) reused for many solves, docs/method.md §2 "factorize once, then one
// multi-right-hand-side solve per iteration".
// Threads: a solve only reads the factor; what it writes lives in a Workspace (its own
// cholmod_common and the X, Y, E buffers of cholmod_solve2, CHOLMOD user guide §"cholmod_solve2").
// Threads that each pass their own Workspace may call solve at the same time: simplicial solves
// then run at once, supernodal ones (which call the BLAS) one after the other (cholmod_factor.cpp).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "stcontact/linalg/spd_solver.hpp"

namespace stc {

class CholmodFactor final : public SpdSolver {
 public:
  /// Factorises A (symmetric positive definite, lower triangle used). Throws InputError naming
  /// `what` if A is not positive definite (e.g. Dirichlet conditions that leave a rigid motion free).
  CholmodFactor(const Eigen::SparseMatrix<double>& A, const std::string& what);
  /// The same factor with the dofs J = `trailing` (distinct) ordered after every other, in the
  /// order given, the rest in CHOLMOD's fill-reducing order, when that pays: |J| · lnz ≥ `min_work`
  /// (the |J| solves that condensed() saves cost about 4 |J| lnz flops), the dense trailing block
  /// costs at most kTrailingFlopShare times the plain factorisation (|J|³ / 3 ≤ share · fl) and
  /// holds at most kTrailingBytes; else the plain factor. The trailing block of L is the Cholesky
  /// factor of the Schur complement of A on J (linalg/detail/cholmod_trailing.hpp), kept dense, and
  /// condensed() uses it.
  /// `max_bytes`: FactorTooLarge when bytesOf(the plain factor's entries) exceeds it.
  CholmodFactor(const Eigen::SparseMatrix<double>& A, const std::string& what, const std::vector<int>& trailing,
                double min_work = kTrailingWork, double max_bytes = kNoMemoryBound);
  static constexpr double kNoMemoryBound = 1e300;
  ~CholmodFactor() override;

  /// X = A⁻¹ B for all columns of B, by chunks of kChunk columns (kSupernodalChunk for a supernodal
  /// factor; the chunks fix the arithmetic: the same B gives the same X whichever workspace or
  /// thread solves it).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B, Workspace& workspace) const override;
  using SpdSolver::solve;  // with the factor's own workspace: one thread at a time
  /// The same chunks handed out to threadCount() threads, each with a workspace of its own (a
  /// supernodal factor on a BLAS that does not take concurrent calls: solve(B) on this thread):
  /// bitwise solve(B)'s result on any thread count.
  /// For the many-column solves of one caller (the Delassus operator of the incremental solver);
  /// not from inside a parallelFor body (src/core/threads.hpp).
  Eigen::MatrixXd solveOnThreads(const Eigen::MatrixXd& B) const override;
  /// The columns of B in parts of `part` columns (1 ≤ part ≤ kChunk, one CHOLMOD call each), handed
  /// out in order to threadCount() threads, thread t solving with workspaces[t] (added as needed, kept
  /// for the next call). A part is solved the same way on any thread, so the result does not depend
  /// on the thread count; narrow parts spread few columns over the threads (the separated stage's
  /// new directions, about 8 at a time: pgd/response_basis.cpp). A supernodal factor's parts are
  /// solve(B)'s chunks of kSupernodalChunk, whatever `part` (1 ≤ part ≤ kSupernodalChunk there), and
  /// on a BLAS that does not take concurrent calls the whole of B is solved on this thread with
  /// workspaces[0], as solve(B, workspaces[0]). Not from inside a parallelFor body.
  Eigen::MatrixXd solveInParts(const Eigen::MatrixXd& B, int part, std::vector<Workspace>& workspaces) const override;
  /// Whether every nonzero column of C (r × n) is a trailing dof of this factor, so that condensed(C)
  /// needs no solve.
  bool condenses(const Eigen::SparseMatrix<double>& C) const override;
  /// C A⁻¹ Cᵀ (r × r, symmetric) for a C that condenses(): with (A⁻¹)_JJ = (L_JJ L_JJᵀ)⁻¹ on the
  /// trailing dofs J, C A⁻¹ Cᵀ = Yᵀ Y, Y = L_JJ⁻¹ C_Jᵀ (a dense triangular solve on |J| rows). Throws
  /// std::invalid_argument for another C.
  Eigen::MatrixXd condensed(const Eigen::SparseMatrix<double>& C) const override;
  /// A⁻¹ Rᵀ U for an R that condenses() (r × n, U: r × k): with P A Pᵀ = L Lᵀ and Rᵀ U nonzero on
  /// the trailing dofs alone, the forward solve is L_JJ⁻¹ on the trailing block (dense), and only the
  /// backward solve with Lᵀ is sparse: about half a solve per column. By chunks as solve(B), handed
  /// out to the threads as solveOnThreads does (the same bits on any thread count). Throws
  /// std::invalid_argument for another R.
  Eigen::MatrixXd solveFromTrailing(const Eigen::SparseMatrix<double>& R, const Eigen::MatrixXd& U) const override;
  /// The memory of a factor with `entries` entries of L: 8 bytes each, times kBytesPerEntry for the
  /// explicit zeros of supernodal amalgamation and the workspace (measured: 4.14 GB of resident
  /// growth for 4.04e8 entries on the half-ball at 335k dofs, docs/linear_solvers.md).
  static double bytesOf(double entries) { return 8.0 * kBytesPerEntry * entries; }
  static constexpr double kBytesPerEntry = 1.3;
  int size() const override;
  std::string backend() const override { return "cholmod"; }
  bool isDirect() const override { return true; }
  /// Whether the factor is kept supernodal (fl / lnz ≥ kSupernodalSolveSwitch: the 3D meshes), solved
  /// through the BLAS: by one thread at a time unless the BLAS takes concurrent calls.
  bool isSupernodal() const;
  /// Entries of the Cholesky factor L as CHOLMOD's analysis counts them (cholmod_common::lnz:
  /// without the explicit zeros of supernodal amalgamation): its memory is about 8 bytes each.
  double factorNonZeros() const override;

  /// Right-hand sides per CHOLMOD call: bounds the workspace (n × kChunk); the simplicial solve
  /// costs the same per column from 4 to 32 at once (measured, cholmod_factor.cpp).
  static constexpr int kChunk = 16;
  /// Right-hand sides per call for a supernodal factor: its BLAS level-3 solve costs 2.3 ms per
  /// column by 16 and 1.9 by 32 on the half-ball at divisions 12 (cholmod_factor.cpp).
  static constexpr int kSupernodalChunk = 32;
  /// Flops of the factorisation per entry of L from which a supernodal factor is kept supernodal
  /// for its solves (else made simplicial): 2D meshes measured up to 67, the 3D half-ball from 104
  /// (cholmod_factor.cpp).
  static constexpr double kSupernodalSolveSwitch = 100.0;
  /// Flops of a factorisation from which OpenBLAS's threads compute its supernodes' dense calls
  /// (linalg::BlasThreadsScope), where the BLAS takes concurrent calls: threaded, the factor's last
  /// bits depend on the thread count, so only a factorisation that takes seconds on one core is
  /// (the half-ball from about divisions 16; 1.2 to 1.7 times faster on two threads at divisions 20,
  /// docs/threads.md, "OpenBLAS's pthread build"); every 2D mesh and small 3D one keeps the bits of
  /// one thread.
  static constexpr double kThreadedFactorFlops = 1e10;
  /// |trailing| · lnz from which the trailing dofs are ordered last: the incremental solver's zone
  /// is faster so from 1.8e8 on, slower at 3.8e7 and below (docs/threads.md, "The Delassus operator
  /// from the factorisation").
  static constexpr double kTrailingWork = 1e8;
  /// Bounds on the dense trailing block: its flops against the plain factorisation's (1601 arc
  /// nodes' zone: 4.8 times, and faster; their whole interface: 205 times), and its memory (the
  /// half-ball's whole interface at divisions 12, 5043 dofs, would hold 203 MB).
  static constexpr double kTrailingFlopShare = 10.0;
  static constexpr double kTrailingBytes = 128.0 * 1024 * 1024;

 private:
  /// body(begin, width, workspace) for the parts of `part` columns of `columns`, handed out in order
  /// to threadCount() threads (inside a parallelFor body: in order on this thread), thread t with
  /// workspaces[t].
  void onThreads(Eigen::Index columns, int part, std::vector<Workspace>& workspaces,
                 const std::function<void(Eigen::Index, Eigen::Index, Workspace&)>& body) const;
  struct Impl;
  std::unique_ptr<Impl> impl_;
  void factorise(const Eigen::SparseMatrix<double>& A, const std::string& what, const std::vector<int>& trailing,
                 double min_work, double max_bytes);
  void keepTrailing(const std::vector<int>& trailing);
  /// C_Jᵀ (|J| × r): C's columns on the trailing dofs, in their order; throws std::invalid_argument
  /// naming `caller` when C reads another dof.
  Eigen::SparseMatrix<double> trailingPart(const Eigen::SparseMatrix<double>& C, const char* caller) const;
};

}  // namespace stc
