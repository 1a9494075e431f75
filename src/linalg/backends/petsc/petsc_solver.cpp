#include "stcontact/linalg/backends/petsc/petsc_solver.hpp"

#include <petscksp.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "stcontact/core/input_error.hpp"

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
      : n_(static_cast<int>(A.rows())), backend_(options.backend), ranks_(currentRanks()),
        comm_(ranks_.size > 1 ? PETSC_COMM_WORLD : PETSC_COMM_SELF),
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
  double factor_entries_ = 0.0;
  mutable std::mutex mutex_;
  mutable KrylovCounts counts_;

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
      throw FactorTooLarge("the MUMPS factor of " + what + " would take about " + std::to_string(estimate / 1e9) +
                           " GB on a rank, more than the " + std::to_string(max_bytes / 1e9) + " GB allowed");
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
  }

  // The relative residual alone (PETSC_DEFAULT keeps the others as they are).
  void setRtol(double rtol) const {
    check(KSPSetTolerances(ksp_, rtol, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT), "KSPSetTolerances");
  }

  void destroy() {
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

  // x = A⁻¹ b by CG to the relative residual, from x = 0.
  void solveColumn(const double* b, double* x) const {
    Vec vb = nullptr, vx = nullptr;
    if (ranks_.size == 1) {
      check(VecCreateSeqWithArray(comm_, 1, rows_.count, b, &vb), "VecCreateSeqWithArray");
    } else {
      check(VecCreateMPIWithArray(comm_, 1, rows_.count, n_, b + rows_.begin, &vb), "VecCreateMPIWithArray");
    }
    check(VecDuplicate(vb, &vx), "VecDuplicate");
    const PetscErrorCode code = KSPSolve(ksp_, vb, vx);
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    PetscInt iterations = 0;
    KSPGetConvergedReason(ksp_, &reason);
    KSPGetIterationNumber(ksp_, &iterations);
    if (code == 0) {
      const PetscScalar* values = nullptr;
      VecGetArrayRead(vx, &values);
      gather(values, x);
      VecRestoreArrayRead(vx, &values);
    }
    VecDestroy(&vb);
    VecDestroy(&vx);
    check(code, "KSPSolve");
    ++counts_.solves;
    counts_.iterations += iterations;
    counts_.max_iterations = std::max(counts_.max_iterations, static_cast<int>(iterations));
    if (reason < 0)
      throw LinearSolveFailure("the cg-gamg linear solve did not converge: " + std::string(KSPConvergedReasons[reason]) +
                               " after " + std::to_string(iterations) +
                               " iterations (solver.linear_max_iterations, solver.linear_rtol; or solver.linear = "
                               "\"mumps\" or \"cholmod\")");
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
