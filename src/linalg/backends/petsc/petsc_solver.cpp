#include "stcontact/linalg/backends/petsc/petsc_solver.hpp"

#include <petscksp.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/memory.hpp"

namespace stc {
namespace {

// A PETSc call that failed: std::runtime_error naming the call (PETSc's own message is not printed:
// PetscReturnErrorHandler, below).
void check(PetscErrorCode code, const char* call) {
  if (code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  throw std::runtime_error(std::string("PETSc: ") + call + " failed (" + (text ? text : "error " + std::to_string(code)) + ")");
}

// PETSc (and MPI, which it starts when no one has) initialised once per process, finalised at
// exit, after every solver object is gone (their owners are destroyed when main returns or the
// interpreter ends, before the handlers of std::atexit run).
void ensurePetsc() {
  static std::once_flag once;
  std::call_once(once, [] {
    PetscBool ready = PETSC_FALSE;
    check(PetscInitialized(&ready), "PetscInitialized");
    if (ready) return;
    if (!std::getenv("OMPI_COMM_WORLD_SIZE")) {
      // One process without a launcher (Open MPI's singleton): it starts no other rank, so it needs
      // no ssh to start them and no cross-memory attach, which a container may lack. The user's
      // settings win (no overwrite).
      setenv("OMPI_MCA_plm", "isolated", 0);
      setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", 0);
    }
    check(PetscInitializeNoArguments(), "PetscInitializeNoArguments");
    check(PetscPushErrorHandler(PetscReturnErrorHandler, nullptr), "PetscPushErrorHandler");
    std::atexit([] { PetscFinalize(); });
  });
}

// Which rows a rank owns: contiguous blocks, the first n mod size ranks one row more.
struct RowBlock {
  PetscInt begin = 0, count = 0;
};

RowBlock rowBlockOf(PetscInt n, const Ranks& ranks) {
  const PetscInt base = n / ranks.size, extra = n % ranks.size;
  return {ranks.rank * base + std::min<PetscInt>(ranks.rank, extra), base + (ranks.rank < extra ? 1 : 0)};
}

// The ranks split into `count` groups of consecutive ranks (LinearSolverOptions::groups), each with a
// communicator of its own: group g holds world ranks [g P/count, (g + 1) P/count), its first one its
// leader. Columns split in contiguous parts, the first cols mod count groups one column more.
struct RankGroups {
  int count = 1;
  int index = 0;           ///< this rank's group
  Ranks within;            ///< this rank's place in its group
  MPI_Comm comm = MPI_COMM_NULL;

  RankGroups(const LinearSolverOptions& options, const Ranks& world) : count(options.groups) {
    options.requireGroupsDivide(world.size);
    const int per_group = world.size / count;
    index = world.rank / per_group;
    within = {world.rank % per_group, per_group};
    check(MPI_Comm_split(PETSC_COMM_WORLD, index, world.rank, &comm), "MPI_Comm_split");
  }
  ~RankGroups() {
    if (comm != MPI_COMM_NULL) MPI_Comm_free(&comm);
  }
  RankGroups(const RankGroups&) = delete;
  RankGroups& operator=(const RankGroups&) = delete;

  RowBlock columnsOf(int group, Eigen::Index cols) const { return rowBlockOf(static_cast<PetscInt>(cols), {group, count}); }

  // X (n × cols) with this group's columns solved, on every rank of it: every column on every rank,
  // from each group's leader (MPI_Allgatherv in place over the world's ranks, column-major blocks;
  // the other ranks of a group send nothing).
  void exchange(Eigen::MatrixXd& X) const {
    const int world_size = count * within.size;
    std::vector<int> counts(static_cast<std::size_t>(world_size), 0), starts(counts.size(), 0);
    for (int group = 0; group < count; ++group) {
      const RowBlock part = columnsOf(group, X.cols());
      const auto leader = static_cast<std::size_t>(group * within.size);
      counts[leader] = static_cast<int>(part.count * X.rows());
      starts[leader] = static_cast<int>(part.begin * X.rows());
    }
    check(MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, X.data(), counts.data(), starts.data(), MPI_DOUBLE,
                         PETSC_COMM_WORLD),
          "MPI_Allgatherv");
  }
};

// A (lower triangle used, as CHOLMOD's) as an AIJ matrix holding both triangles: sequential on one
// rank, else this rank's block of rows of the distributed one.
Mat toPetsc(const Eigen::SparseMatrix<double>& A, MPI_Comm comm, const RowBlock& rows) {
  using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor, PetscInt>;
  RowMajor full = A.selfadjointView<Eigen::Lower>();
  full.makeCompressed();
  Mat M = nullptr;
  const auto n = static_cast<PetscInt>(A.rows());
  PetscMPIInt size = 1;
  MPI_Comm_size(comm, &size);
  if (size == 1) {
    check(MatCreate(comm, &M), "MatCreate");
    check(MatSetSizes(M, n, n, n, n), "MatSetSizes");
    check(MatSetType(M, MATSEQAIJ), "MatSetType");
    check(MatSeqAIJSetPreallocationCSR(M, full.outerIndexPtr(), full.innerIndexPtr(), full.valuePtr()),
          "MatSeqAIJSetPreallocationCSR");
  } else {  // this rank's rows, their offsets counted from the block's first entry
    const PetscInt* outer = full.outerIndexPtr() + rows.begin;
    std::vector<PetscInt> offsets(outer, outer + rows.count + 1);
    for (PetscInt& o : offsets) o -= outer[0];
    check(MatCreateMPIAIJWithArrays(comm, rows.count, rows.count, n, n, offsets.data(), full.innerIndexPtr() + outer[0],
                                    full.valuePtr() + outer[0], &M),
          "MatCreateMPIAIJWithArrays");
  }
  check(MatSetOption(M, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
  check(MatSetOption(M, MAT_SYMMETRY_ETERNAL, PETSC_TRUE), "MatSetOption");
  return M;
}

// The columns of R (n × k) as PETSc's near-null space of M.
void setNearNullSpace(Mat M, const Eigen::MatrixXd& R, MPI_Comm comm, const RowBlock& rows) {
  if (R.cols() == 0) return;
  std::vector<Vec> vectors(static_cast<std::size_t>(R.cols()));
  for (Eigen::Index j = 0; j < R.cols(); ++j) {
    check(MatCreateVecs(M, &vectors[static_cast<std::size_t>(j)], nullptr), "MatCreateVecs");
    PetscScalar* v = nullptr;
    check(VecGetArray(vectors[static_cast<std::size_t>(j)], &v), "VecGetArray");
    std::copy(R.col(j).data() + rows.begin, R.col(j).data() + rows.begin + rows.count, v);
    check(VecRestoreArray(vectors[static_cast<std::size_t>(j)], &v), "VecRestoreArray");
  }
  MatNullSpace space = nullptr;
  check(MatNullSpaceCreate(comm, PETSC_FALSE, static_cast<PetscInt>(R.cols()), vectors.data(), &space),
        "MatNullSpaceCreate");
  check(MatSetNearNullSpace(M, space), "MatSetNearNullSpace");
  check(MatNullSpaceDestroy(&space), "MatNullSpaceDestroy");
  for (Vec& v : vectors) check(VecDestroy(&v), "VecDestroy");
}

class PetscSolver final : public SpdSolver {
 public:
  PetscSolver(const Eigen::SparseMatrix<double>& A, const std::string& what, const LinearSolverOptions& options,
              const std::function<Eigen::MatrixXd()>& near_null_space, double max_factor_bytes)
      : PetscSolver(A, what, options, near_null_space, max_factor_bytes, currentRanks(), PETSC_COMM_WORLD) {
    // cg-gamg on several ranks in groups: each group's own copy of A and of its hierarchy, which
    // solves its part of a block's columns (solveInGroups).
    if (backend_ != LinearBackend::CgGamg || ranks_.size == 1 || options.groups == 1) return;
    groups_ = std::make_unique<RankGroups>(options, ranks_);
    LinearSolverOptions within = options;
    within.groups = 1;
    group_ = std::unique_ptr<PetscSolver>(
        new PetscSolver(A, what, within, near_null_space, max_factor_bytes, groups_->within, groups_->comm));
  }

  // On the ranks `ranks` of `comm` (PETSC_COMM_SELF for one).
  PetscSolver(const Eigen::SparseMatrix<double>& A, const std::string& what, const LinearSolverOptions& options,
              const std::function<Eigen::MatrixXd()>& near_null_space, double max_factor_bytes, const Ranks& ranks,
              MPI_Comm comm)
      : n_(static_cast<int>(A.rows())), backend_(options.backend), ranks_(ranks),
        comm_(ranks_.size > 1 ? comm : PETSC_COMM_SELF),
        rows_(rowBlockOf(static_cast<PetscInt>(A.rows()), ranks_)) {
    ensurePetsc();
    try {
      matrix_ = toPetsc(A, comm_, rows_);
      if (backend_ == LinearBackend::Mumps) factorise(what, max_factor_bytes);
      else prepareKrylov(options, near_null_space);
    } catch (...) {  // a refused operator (not positive definite, too large) leaves no PETSc object behind
      destroy();
      throw;
    }
  }

  ~PetscSolver() override { destroy(); }

  Eigen::MatrixXd solve(const Eigen::MatrixXd& B, Workspace&) const override {
    if (B.rows() != n_) throw std::invalid_argument("SpdSolver::solve: right-hand side has the wrong number of rows");
    Eigen::MatrixXd X(n_, B.cols());
    if (B.cols() == 0) return X;
    if (group_ && B.cols() > 1) return solveInGroups(B, Eigen::VectorXd::Ones(B.cols()));
    const std::lock_guard<std::mutex> lock(mutex_);
    if (backend_ == LinearBackend::Mumps) solveDirect(B, X);
    else for (Eigen::Index j = 0; j < B.cols(); ++j) solveColumn(B.col(j).data(), X.col(j).data());
    return X;
  }

  // Column j to the relative residual min(rtol ℓ_j, kLoosestRtol) (never looser than rtol itself);
  // the loosenings agreed among the ranks first (the smallest of each), since every rank's KSPSolve
  // of one column must stop at the same iteration. solve() is back at rtol after it, thrown or not.
  Eigen::MatrixXd solveLoosened(const Eigen::MatrixXd& B, const Eigen::VectorXd& loosening) const override {
    checkLoosening(B, loosening);
    if (backend_ == LinearBackend::Mumps) return SpdSolver::solve(B);
    if (B.rows() != n_) throw std::invalid_argument("SpdSolver::solve: right-hand side has the wrong number of rows");
    Eigen::VectorXd agreed = loosening;
    if (ranks_.size > 1)
      MPI_Allreduce(loosening.data(), agreed.data(), static_cast<int>(agreed.size()), MPI_DOUBLE, MPI_MIN, comm_);
    if (group_ && B.cols() > 1) return solveInGroups(B, agreed);
    const double loosest = std::max(rtol_, LinearSolverOptions::kLoosestRtol);
    Eigen::MatrixXd X(n_, B.cols());
    const std::lock_guard<std::mutex> lock(mutex_);
    try {
      for (Eigen::Index j = 0; j < B.cols(); ++j) {
        setRtol(std::min(rtol_ * agreed[j], loosest));
        solveColumn(B.col(j).data(), X.col(j).data());
      }
    } catch (...) {
      KSPSetTolerances(ksp_, rtol_, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT);
      throw;
    }
    setRtol(rtol_);
    return X;
  }

  bool holdsDofs() const override { return backend_ == LinearBackend::CgGamg; }

  // A copy of A with `replaced`'s rows set and the held rows and columns zeroed (MatZeroRowsColumns:
  // the diagonal set to A's mean diagonal, the held values moved to the right-hand side), solved
  // from x0 by CG (GMRES, right-preconditioned, when rows were replaced) with the GAMG hierarchy of
  // A itself as preconditioner (set up once, never again); the held entries of the result are
  // x0's exactly (the Krylov steps may touch them by round-off of the preconditioner).
  Eigen::VectorXd solveHeld(const Eigen::VectorXd& b, const std::vector<int>& held, const Eigen::VectorXd& x0,
                            const ReplacedRows& replaced) const override {
    if (backend_ != LinearBackend::CgGamg) return SpdSolver::solveHeld(b, held, x0, replaced);
    if (b.size() != n_ || x0.size() != n_ || replaced.rows.rows() != static_cast<Eigen::Index>(replaced.dofs.size()) ||
        (!replaced.dofs.empty() && replaced.rows.cols() != n_))
      throw std::invalid_argument("SpdSolver::solveHeld: right-hand side, start or replaced rows of the wrong size");
    Eigen::VectorXd x(n_);
    const std::lock_guard<std::mutex> lock(mutex_);
    const KSP ksp = replaced.dofs.empty() ? ksp_ : gmres();  // before any object that a throw would leak
    Mat held_matrix = nullptr;
    Vec vb = localCopy(b), vx = localCopy(x0);
    PetscErrorCode code = MatDuplicate(matrix_, MAT_COPY_VALUES, &held_matrix);
    if (code == 0) code = replaceRows(held_matrix, replaced);
    const std::vector<PetscInt> local = ownedAmong(held);  // MatZeroRowsColumns' global indices
    if (code == 0)
      code = MatZeroRowsColumns(held_matrix, static_cast<PetscInt>(local.size()), local.data(), mean_diagonal_, vx, vb);
    if (code == 0) code = KSPSetOperators(ksp, held_matrix, matrix_);
    if (code == 0) code = KSPSetInitialGuessNonzero(ksp, PETSC_TRUE);
    const KrylovRun run = code == 0 ? krylovSolve(ksp, vb, vx, x.data()) : KrylovRun{code};
    KSPSetInitialGuessNonzero(ksp, PETSC_FALSE);
    KSPSetOperators(ksp_, matrix_, matrix_);
    MatDestroy(&held_matrix);
    VecDestroy(&vb);
    VecDestroy(&vx);
    check(run.code, "KSPSolve (held dofs)");
    count(run);
    for (int h : held) x[h] = x0[h];
    return x;
  }

  int size() const override { return n_; }
  std::string backend() const override { return backend_ == LinearBackend::Mumps ? "mumps" : "cg-gamg"; }
  bool isDirect() const override { return backend_ == LinearBackend::Mumps; }
  double factorNonZeros() const override { return factor_entries_; }
  KrylovCounts krylovCounts() const override {
    const std::lock_guard<std::mutex> lock(mutex_);
    return counts_;
  }

 private:
  int n_;
  LinearBackend backend_;
  Ranks ranks_;
  MPI_Comm comm_;
  RowBlock rows_;  ///< this rank's rows
  double rtol_ = LinearSolverOptions::kRtolFloor;  ///< cg-gamg: the relative residual of solve()
  Mat matrix_ = nullptr;
  Mat factor_ = nullptr;  ///< mumps: MUMPS's factor of matrix_
  KSP ksp_ = nullptr;     ///< cg-gamg
  mutable KSP gmres_ = nullptr;  ///< cg-gamg: solveHeld's when rows are replaced, made on first use
  static constexpr PetscInt kGmresRestart = 200;  ///< no restart within the iterations a warm solve takes
  double mean_diagonal_ = 1.0;  ///< cg-gamg: A's, the diagonal of solveHeld's held rows
  double factor_entries_ = 0.0;
  mutable std::mutex mutex_;
  mutable KrylovCounts counts_;
  std::unique_ptr<RankGroups> groups_;  ///< cg-gamg on ranks in groups (LinearSolverOptions::groups)
  std::unique_ptr<PetscSolver> group_;  ///< this rank's group's solver (destroyed before groups_'s communicator)

  // MUMPS's Cholesky factor of A (SYM = 2: LDLᵀ, its negative pivots counted), PETSc's options
  // (prefix "stc_": -stc_mat_mumps_icntl_14 …) read at the analysis. Refused after the analysis
  // when its estimate of the factorisation's memory on the largest rank exceeds `max_bytes`;
  // refused after the factorisation when A is not positive definite.
  void factorise(const std::string& what, double max_bytes) {
    check(MatGetFactor(matrix_, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, &factor_), "MatGetFactor (MUMPS)");
    check(MatSetOptionsPrefix(factor_, "stc_"), "MatSetOptionsPrefix");
    MatFactorInfo info;
    check(MatFactorInfoInitialize(&info), "MatFactorInfoInitialize");
    IS rows = nullptr, cols = nullptr;  // MUMPS orders A itself
    check(MatGetOrdering(matrix_, MATORDERINGNATURAL, &rows, &cols), "MatGetOrdering");
    const PetscErrorCode analysed = MatCholeskyFactorSymbolic(factor_, matrix_, rows, &info);
    ISDestroy(&rows);
    ISDestroy(&cols);
    check(analysed, "MatCholeskyFactorSymbolic (MUMPS)");
    // INFOG(16) in whole MB, so for a small factor its entries (INFOG(20), −millions when large)
    // shared by the ranks.
    const double entries = infog(20) >= 0 ? static_cast<double>(infog(20)) : -1e6 * static_cast<double>(infog(20));
    const double estimate = std::max(1e6 * static_cast<double>(infog(16)), 8.0 * entries / ranks_.size);
    if (estimate > max_bytes)
      throw FactorTooLarge("the MUMPS factor of " + what + " would take about " + bytesText(estimate) +
                           " on a rank, more than the " + bytesText(max_bytes) + " allowed");
    check(MatCholeskyFactorNumeric(factor_, matrix_, &info), "MatCholeskyFactorNumeric (MUMPS)");
    checkFactor(what);
  }

  // CG on the unpreconditioned residual with GAMG, the near-null space given; the AMG hierarchy set
  // up now, PETSc's options (prefix "stc_") applied last.
  void prepareKrylov(const LinearSolverOptions& options, const std::function<Eigen::MatrixXd()>& near_null_space) {
    if (near_null_space) setNearNullSpace(matrix_, near_null_space(), comm_, rows_);
    check(KSPCreate(comm_, &ksp_), "KSPCreate");
    check(KSPSetOptionsPrefix(ksp_, "stc_"), "KSPSetOptionsPrefix");
    check(KSPSetOperators(ksp_, matrix_, matrix_), "KSPSetOperators");
    check(KSPSetType(ksp_, KSPCG), "KSPSetType");
    check(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
    if (options.rtol > 0.0) rtol_ = options.rtol;
    check(KSPSetTolerances(ksp_, rtol_, 0.0, PETSC_DEFAULT, options.max_iterations), "KSPSetTolerances");
    PC pc = nullptr;
    check(KSPGetPC(ksp_, &pc), "KSPGetPC");
    check(PCSetType(pc, PCGAMG), "PCSetType");
    check(KSPSetFromOptions(ksp_), "KSPSetFromOptions");
    PetscReal rtol = 0.0;  // an expert's -stc_ksp_rtol wins, here as in solve()
    check(KSPGetTolerances(ksp_, &rtol, nullptr, nullptr, nullptr), "KSPGetTolerances");
    rtol_ = rtol;
    check(KSPSetUp(ksp_), "KSPSetUp");  // the AMG hierarchy
    check(KSPSetReusePreconditioner(ksp_, PETSC_TRUE), "KSPSetReusePreconditioner");  // for solveHeld's operators
    Vec diagonal = nullptr;
    check(MatCreateVecs(matrix_, &diagonal, nullptr), "MatCreateVecs");
    check(MatGetDiagonal(matrix_, diagonal), "MatGetDiagonal");
    PetscScalar sum = 0.0;
    check(VecSum(diagonal, &sum), "VecSum");
    check(VecDestroy(&diagonal), "VecDestroy");
    mean_diagonal_ = sum / n_;
  }

  // X = A⁻¹ B with each group solving its contiguous part of B's columns on its own ranks, column j
  // to the relative residual min(rtol ℓ_j, kLoosestRtol) (`loosening`, agreed among the ranks), then
  // every column on every rank. The Krylov counts are the groups' summed (their largest for the
  // most one column took). A column that fails in one group fails the solve on every rank.
  Eigen::MatrixXd solveInGroups(const Eigen::MatrixXd& B, const Eigen::VectorXd& loosening) const {
    // MPI counts are ints: blocks of at most 2^30 entries per exchange.
    const Eigen::Index widest = std::max<Eigen::Index>(groups_->count, (Eigen::Index{1} << 30) / std::max(n_, 1));
    if (B.cols() > widest) {
      Eigen::MatrixXd X(n_, B.cols());
      for (Eigen::Index begin = 0; begin < B.cols(); begin += widest) {
        const Eigen::Index count = std::min(widest, B.cols() - begin);
        X.middleCols(begin, count) = solveInGroups(B.middleCols(begin, count), loosening.segment(begin, count));
      }
      return X;
    }
    const RowBlock mine = groups_->columnsOf(groups_->index, B.cols());
    Eigen::MatrixXd X(n_, B.cols());  // every column written: this group's here, the others' by exchange
    const KrylovCounts before = group_->krylovCounts();
    int failed = 0;
    std::string reason;
    try {
      if (mine.count > 0)
        X.middleCols(mine.begin, mine.count) =
            group_->solveLoosened(B.middleCols(mine.begin, mine.count), loosening.segment(mine.begin, mine.count));
    } catch (const std::exception& error) {
      failed = 1;
      reason = error.what();
    }
    const KrylovCounts after = group_->krylovCounts();
    const bool leader = groups_->within.rank == 0;
    long long spent[3] = {leader ? after.solves - before.solves : 0, leader ? after.iterations - before.iterations : 0,
                          failed};
    long long most = after.max_iterations;
    check(MPI_Allreduce(MPI_IN_PLACE, spent, 3, MPI_LONG_LONG, MPI_SUM, comm_), "MPI_Allreduce");
    check(MPI_Allreduce(MPI_IN_PLACE, &most, 1, MPI_LONG_LONG, MPI_MAX, comm_), "MPI_Allreduce");
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      counts_.solves += spent[0];
      counts_.iterations += spent[1];
      counts_.max_iterations = std::max(counts_.max_iterations, static_cast<int>(most));
    }
    if (spent[2] > 0)
      throw LinearSolveFailure(failed ? reason : "the cg-gamg linear solve did not converge on another group of ranks");
    groups_->exchange(X);
    return X;
  }

  // The relative residual alone (PETSC_DEFAULT keeps the others as they are).
  void setRtol(double rtol) const {
    check(KSPSetTolerances(ksp_, rtol, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT), "KSPSetTolerances");
  }

  void destroy() {
    KSPDestroy(&gmres_);
    KSPDestroy(&ksp_);
    MatDestroy(&factor_);
    MatDestroy(&matrix_);
  }

  PetscInt infog(PetscInt i) const {
    PetscInt value = 0;
    check(MatMumpsGetInfog(factor_, i, &value), "MatMumpsGetInfog");
    return value;
  }

  // MUMPS's verdict on A: singular (INFOG(1) < 0) or with negative pivots (INFOG(12) > 0) is not
  // positive definite; INFOG(29) is the number of entries in the factors.
  void checkFactor(const std::string& what) {
    if (infog(1) < 0 || infog(12) > 0)
      throw InputError(what + " is not positive definite (do the Dirichlet conditions fix every rigid-body motion?)");
    factor_entries_ = static_cast<double>(infog(29));
  }

  // X = A⁻¹ B by MUMPS's multiple right-hand-side solve: this rank's rows of B in, every rank's rows
  // of X gathered.
  void solveDirect(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) const {
    Mat b = nullptr, x = nullptr;
    const auto cols = static_cast<PetscInt>(B.cols());
    Eigen::MatrixXd local_b = B.middleRows(rows_.begin, rows_.count), local_x(rows_.count, B.cols());
    if (ranks_.size == 1) {
      check(MatCreateSeqDense(comm_, rows_.count, cols, local_b.data(), &b), "MatCreateSeqDense");
      check(MatCreateSeqDense(comm_, rows_.count, cols, local_x.data(), &x), "MatCreateSeqDense");
    } else {
      check(MatCreateDense(comm_, rows_.count, PETSC_DECIDE, n_, cols, local_b.data(), &b), "MatCreateDense");
      check(MatCreateDense(comm_, rows_.count, PETSC_DECIDE, n_, cols, local_x.data(), &x), "MatCreateDense");
    }
    const PetscErrorCode code = MatMatSolve(factor_, b, x);
    MatDestroy(&b);
    MatDestroy(&x);
    check(code, "MatMatSolve (MUMPS)");
    for (Eigen::Index j = 0; j < B.cols(); ++j) gather(local_x.col(j).data(), X.col(j).data());
  }

  // The whole column from every rank's block of it (MPI_Allgatherv); a copy on one rank.
  void gather(const double* local, double* whole) const {
    if (ranks_.size == 1) {
      std::copy(local, local + rows_.count, whole);
      return;
    }
    std::vector<int> counts(static_cast<std::size_t>(ranks_.size)), starts(counts.size());
    for (int r = 0; r < ranks_.size; ++r) {
      const RowBlock block = rowBlockOf(n_, {r, ranks_.size});
      counts[static_cast<std::size_t>(r)] = static_cast<int>(block.count);
      starts[static_cast<std::size_t>(r)] = static_cast<int>(block.begin);
    }
    MPI_Allgatherv(local, static_cast<int>(rows_.count), MPI_DOUBLE, whole, counts.data(), starts.data(), MPI_DOUBLE,
                   comm_);
  }

  // The dofs of `dofs` this rank owns.
  std::vector<PetscInt> ownedAmong(const std::vector<int>& dofs) const {
    std::vector<PetscInt> out;
    for (int d : dofs)
      if (d >= rows_.begin && d < rows_.begin + rows_.count) out.push_back(d);
    return out;
  }

  // The rows of `replaced` this rank owns written over M's (zeroed first, their pattern kept),
  // then assembled.
  PetscErrorCode replaceRows(Mat M, const ReplacedRows& replaced) const {
    if (replaced.dofs.empty()) return 0;
    for (const MatOption option : {MAT_SYMMETRIC, MAT_SYMMETRY_ETERNAL})  // A's, no longer
      if (const PetscErrorCode code = MatSetOption(M, option, PETSC_FALSE)) return code;
    if (const PetscErrorCode code = MatSetOption(M, MAT_KEEP_NONZERO_PATTERN, PETSC_TRUE)) return code;
    const std::vector<PetscInt> owned = ownedAmong(replaced.dofs);
    if (const PetscErrorCode code = MatZeroRows(M, static_cast<PetscInt>(owned.size()), owned.data(), 0.0, nullptr, nullptr))
      return code;
    for (std::size_t j = 0; j < replaced.dofs.size(); ++j) {
      const PetscInt row = replaced.dofs[j];
      if (row < rows_.begin || row >= rows_.begin + rows_.count) continue;
      std::vector<PetscInt> cols;
      std::vector<PetscScalar> values;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(replaced.rows, static_cast<Eigen::Index>(j)); it;
           ++it) {
        cols.push_back(static_cast<PetscInt>(it.col()));
        values.push_back(it.value());
      }
      if (const PetscErrorCode code = MatSetValues(M, 1, &row, static_cast<PetscInt>(cols.size()), cols.data(),
                                                   values.data(), INSERT_VALUES))
        return code;
    }
    if (const PetscErrorCode code = MatAssemblyBegin(M, MAT_FINAL_ASSEMBLY)) return code;
    return MatAssemblyEnd(M, MAT_FINAL_ASSEMBLY);
  }

  // solveHeld's Krylov solver for a nonsymmetric operator: GMRES on the unpreconditioned residual
  // (right preconditioning), sharing ksp_'s GAMG hierarchy; made on first use.
  KSP gmres() const {
    if (gmres_) return gmres_;
    PC pc = nullptr;
    check(KSPGetPC(ksp_, &pc), "KSPGetPC");
    check(KSPCreate(comm_, &gmres_), "KSPCreate");
    check(KSPSetOptionsPrefix(gmres_, "stc_held_"), "KSPSetOptionsPrefix");
    check(KSPSetType(gmres_, KSPGMRES), "KSPSetType");
    check(KSPGMRESSetRestart(gmres_, kGmresRestart), "KSPGMRESSetRestart");
    check(KSPSetPCSide(gmres_, PC_RIGHT), "KSPSetPCSide");
    check(KSPSetNormType(gmres_, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
    PetscInt max_iterations = 0;
    check(KSPGetTolerances(ksp_, nullptr, nullptr, nullptr, &max_iterations), "KSPGetTolerances");
    check(KSPSetTolerances(gmres_, rtol_, 0.0, PETSC_DEFAULT, max_iterations), "KSPSetTolerances");
    check(KSPSetPC(gmres_, pc), "KSPSetPC");
    check(KSPSetReusePreconditioner(gmres_, PETSC_TRUE), "KSPSetReusePreconditioner");
    check(KSPSetFromOptions(gmres_), "KSPSetFromOptions");
    return gmres_;
  }

  // What one KSPSolve returned.
  struct KrylovRun {
    PetscErrorCode code = 0;
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    PetscInt iterations = 0;
  };

  // KSPSolve(b, x) and the whole solution gathered into `whole` (when it succeeded).
  KrylovRun krylovSolve(KSP ksp, Vec vb, Vec vx, double* whole) const {
    KrylovRun run;
    run.code = KSPSolve(ksp, vb, vx);
    KSPGetConvergedReason(ksp, &run.reason);
    KSPGetIterationNumber(ksp, &run.iterations);
    if (run.code == 0) {
      const PetscScalar* values = nullptr;
      VecGetArrayRead(vx, &values);
      gather(values, whole);
      VecRestoreArrayRead(vx, &values);
    }
    return run;
  }

  // A solve's iterations counted; a solve that did not converge is a LinearSolveFailure.
  void count(const KrylovRun& run) const {
    ++counts_.solves;
    counts_.iterations += run.iterations;
    counts_.max_iterations = std::max(counts_.max_iterations, static_cast<int>(run.iterations));
    if (run.reason < 0)
      throw LinearSolveFailure("the cg-gamg linear solve did not converge: " +
                               std::string(KSPConvergedReasons[run.reason]) + " after " +
                               std::to_string(run.iterations) +
                               " iterations (solver.linear_max_iterations, solver.linear_rtol; or solver.linear = "
                               "\"mumps\" or \"cholmod\")");
  }

  // This rank's rows of the whole vector `v` in a vector of their own (matrix_'s layout).
  Vec localCopy(const Eigen::VectorXd& v) const {
    Vec out = nullptr;
    check(MatCreateVecs(matrix_, &out, nullptr), "MatCreateVecs");
    PetscScalar* values = nullptr;
    check(VecGetArray(out, &values), "VecGetArray");
    std::copy(v.data() + rows_.begin, v.data() + rows_.begin + rows_.count, values);
    check(VecRestoreArray(out, &values), "VecRestoreArray");
    return out;
  }

  // x = A⁻¹ b by CG to the relative residual, from x = 0.
  void solveColumn(const double* b, double* x) const {
    Vec vb = nullptr, vx = nullptr;
    if (ranks_.size == 1) {
      check(VecCreateSeqWithArray(comm_, 1, rows_.count, b, &vb), "VecCreateSeqWithArray");
    } else {
      check(VecCreateMPIWithArray(comm_, 1, rows_.count, n_, b + rows_.begin, &vb), "VecCreateMPIWithArray");
    }
    check(VecDuplicate(vb, &vx), "VecDuplicate");
    const KrylovRun run = krylovSolve(ksp_, vb, vx, x);
    VecDestroy(&vb);
    VecDestroy(&vx);
    check(run.code, "KSPSolve");
    count(run);
  }
};

}  // namespace

Ranks petscRanks() {
  ensurePetsc();
  PetscMPIInt rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  return {rank, size};
}

std::vector<double> petscAllGather(double value) {
  ensurePetsc();
  PetscMPIInt size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  std::vector<double> values(static_cast<std::size_t>(size));
  MPI_Allgather(&value, 1, MPI_DOUBLE, values.data(), 1, MPI_DOUBLE, PETSC_COMM_WORLD);
  return values;
}

std::unique_ptr<SpdSolver> preparePetscSolver(const Eigen::SparseMatrix<double>& A, const std::string& what,
                                              const LinearSolverOptions& options,
                                              const std::function<Eigen::MatrixXd()>& near_null_space,
                                              double max_factor_bytes) {
  if (options.backend == LinearBackend::Cholmod)
    throw std::logic_error("preparePetscSolver: cholmod is not a PETSc backend");
  return std::make_unique<PetscSolver>(A, what, options, near_null_space, max_factor_bytes);
}

}  // namespace stc
