#include "stcontact/linalg/backends/cholmod_factor.hpp"

#include <Eigen/CholmodSupport>
#include <algorithm>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/memory.hpp"
#include "stcontact/core/threads.hpp"
#include "stcontact/core/worker_pool.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/linalg/detail/cholmod_trailing.hpp"

namespace stc {

namespace {
// A CHOLMOD workspace: what cholmod_solve2 writes on one thread.
struct CholmodWorkspace final : SpdSolver::Workspace::State {
  cholmod_common common;
  cholmod_dense *X = nullptr, *Y = nullptr, *E = nullptr;  ///< cholmod_solve2's solution and buffers
  CholmodWorkspace() {
    cholmod_start(&common);
    common.print = 0;  // failures are thrown, not printed
  }
  ~CholmodWorkspace() override {
    cholmod_free_dense(&X, &common);
    cholmod_free_dense(&Y, &common);
    cholmod_free_dense(&E, &common);
    cholmod_finish(&common);
  }
  CholmodWorkspace(const CholmodWorkspace&) = delete;
  CholmodWorkspace& operator=(const CholmodWorkspace&) = delete;
};

// The CHOLMOD state of `workspace`, made on first use (a workspace another backend filled is
// refilled).
CholmodWorkspace& cholmodState(SpdSolver::Workspace& workspace) {
  if (auto* state = dynamic_cast<CholmodWorkspace*>(workspace.state.get())) return *state;
  workspace.state = std::make_unique<CholmodWorkspace>();
  return static_cast<CholmodWorkspace&>(*workspace.state);
}
}  // namespace

// The factorisation is left to CHOLMOD's own choice (CHOLMOD_AUTO: supernodal when the flop count
// per factor entry fl / lnz reaches common.supernodal_switch = 40). How the factor is solved with
// depends on the same ratio, with a higher switch (kSupernodalSolveSwitch):
// - below it (every 2D mesh measured: fl / lnz from 25 at 1088 dofs to 67 at 52 058) the factor is
//   made simplicial and solved in plain C, by chunks of kChunk, on any number of threads at once,
//   each with its own workspace;
// - from it on (the half-ball from divisions 4: 104, 282 at divisions 6, 698 at 12) it stays
//   supernodal and is solved with the BLAS (dtrsm, dgemm) by chunks of kSupernodalChunk. Debian's
//   serial OpenBLAS 0.3.21 returns wrong columns when two threads call it at once (measured: ~2% of
//   concurrent 16-column solves; none with the reference BLAS; docs/threads.md), so with it every
//   supernodal factorisation and solve holds one process-wide lock: one thread solves. With a BLAS
//   that takes concurrent calls (OpenBLAS's pthread build, linalg/blas_kernels.hpp) the chunks are
//   handed out to the threads like the simplicial ones.
// Why: on the half-ball at divisions 12 (22 500 dofs, 8.6 M entries in L, 288 right-hand sides, one
// thread, bench/bench_cholmod_modes.cpp Solve3d) a simplicial solve costs 6.6 ms per column by
// chunks of 4 to 32, the supernodal one 4.2 ms by 4, 2.3 by 16, 1.9 by 32, so one thread solving
// supernodally beats two solving simplicially; on the 2D meshes the two cost about the same per
// column and the two threads win (docs/threads.md, "A supernodal factor in 3D").
namespace {
// A CHOLMOD view of `cols` column-major columns of `rows` entries at `x` (leading dimension `rows`).
cholmod_dense denseView(const double* x, Eigen::Index rows, Eigen::Index cols) {
  cholmod_dense b{};
  b.nrow = static_cast<std::size_t>(rows);
  b.ncol = static_cast<std::size_t>(cols);
  b.nzmax = b.nrow * b.ncol;
  b.d = b.nrow;
  b.x = const_cast<double*>(x);
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  return b;
}

// Whether the BLAS calls of a factor must take turns: a supernodal one's, on a serial BLAS (above).
bool takesTurns(bool supernodal) { return supernodal && !linalg::blasTakesConcurrentCalls(); }

// The process-wide turn of a factor's BLAS calls where it must take one (takesTurns); else none.
std::unique_lock<std::mutex> blasTurn(bool supernodal) {
  static std::mutex blas;
  return takesTurns(supernodal) ? std::unique_lock<std::mutex>(blas) : std::unique_lock<std::mutex>();
}

// body(c, cols) for the chunks of `columns` columns a solve takes per CHOLMOD call (kSupernodalChunk
// for a supernodal factor, which holds its BLAS turn throughout; kChunk else).
template <class Body>
void inChunks(bool supernodal, Eigen::Index columns, Body&& body) {
  const Eigen::Index chunk = supernodal ? CholmodFactor::kSupernodalChunk : CholmodFactor::kChunk;
  const auto turn = blasTurn(supernodal);
  for (Eigen::Index c = 0; c < columns; c += chunk) body(c, std::min<Eigen::Index>(chunk, columns - c));
}
}  // namespace

struct CholmodFactor::Impl {
  cholmod_common common;
  cholmod_factor* L = nullptr;
  mutable Workspace own;  ///< solveFromTrailing's
  int n = 0;
  Eigen::MatrixXd trailing_factor;     ///< L_JJ, dense lower triangular (empty: no trailing dofs)
  std::vector<int> trailing_position;  ///< per dof: its place among the trailing dofs, −1 if none
  Impl() {
    cholmod_start(&common);
    common.print = 0;  // "not positive definite" is the InputError below, not a line on stdout
    common.final_asis = 0;
    common.supernodal = CHOLMOD_AUTO;
    common.final_ll = 1;
  }
  ~Impl() {
    cholmod_free_factor(&L, &common);
    cholmod_finish(&common);
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
};

CholmodFactor::CholmodFactor(const Eigen::SparseMatrix<double>& A, const std::string& what)
    : impl_(std::make_unique<Impl>()) {
  factorise(A, what, {}, 0.0, kNoMemoryBound);
}

CholmodFactor::CholmodFactor(const Eigen::SparseMatrix<double>& A, const std::string& what, const std::vector<int>& trailing,
                     double min_work, double max_bytes)
    : impl_(std::make_unique<Impl>()) {
  factorise(A, what, trailing, min_work, max_bytes);
}

// Trailing dofs: CHOLMOD's own analysis first (its ordering, and lnz to weigh the solves the
// trailing block saves), then, when that is worth it, the same ordering with the trailing dofs moved
// last, given to CHOLMOD as is (no postordering, which could move them). Ordered last, the
// incremental solver's zone saves its d |Z| solves from |J| · lnz ≈ 1e8 on and costs more below
// (the trailing block makes L larger, 1.75 times in 2D, and every later solve dearer): the
// measurements behind kTrailingWork are in docs/threads.md, "The Delassus operator from the
// factorisation".
void CholmodFactor::factorise(const Eigen::SparseMatrix<double>& A, const std::string& what,
                          const std::vector<int>& trailing, double min_work, double max_bytes) {
  Impl& f = *impl_;
  f.n = static_cast<int>(A.rows());
  cholmod_sparse view = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
  f.L = cholmod_analyze(&view, &f.common);
  if (f.L && bytesOf(f.common.lnz) > max_bytes)
    throw FactorTooLarge("the CHOLMOD factor of " + what + " would take about " + bytesText(bytesOf(f.common.lnz)) +
                         ", more than the " + bytesText(max_bytes) + " allowed");
  const double count = static_cast<double>(trailing.size());
  const bool ordered_last = f.L && count > 0 && count * f.common.lnz >= min_work &&
                            count * count * count / 3.0 <= kTrailingFlopShare * f.common.fl &&
                            8.0 * count * count <= kTrailingBytes;
  if (ordered_last) {
    std::vector<int> order = linalg::orderingWithTrailing(*f.L, trailing);
    cholmod_free_factor(&f.L, &f.common);
    f.common.nmethods = 1;
    f.common.method[0].ordering = CHOLMOD_GIVEN;
    f.common.postorder = 0;
    f.L = cholmod_analyze_p(&view, order.data(), nullptr, 0, &f.common);
    if (f.L && !std::equal(order.begin(), order.end(), static_cast<const int*>(f.L->Perm)))
      throw std::logic_error("CHOLMOD did not keep the given ordering of " + what);
  }
  double beta[2] = {0.0, 0.0};
  if (f.L) {
    const auto turn = blasTurn(f.L->is_super != 0);
    // A large factorisation's supernodes on OpenBLAS's threads (their last bits then the count's).
    const linalg::BlasThreadsScope threads(f.common.fl >= kThreadedFactorFlops ? threadCount() : 1);
    cholmod_factorize_p(&view, beta, nullptr, 0, f.L, &f.common);
  }
  if (!f.L || f.L->minor != f.L->n)
    throw InputError(what + " is not positive definite (do the Dirichlet conditions fix every rigid-body motion?)");
  if (ordered_last) keepTrailing(trailing);
  const bool keep_supernodal = f.common.fl >= kSupernodalSolveSwitch * f.common.lnz;
  if (f.L->is_super && !keep_supernodal && !cholmod_change_factor(CHOLMOD_REAL, 1, 0, 1, 1, f.L, &f.common))
    throw std::runtime_error("CHOLMOD could not convert the supernodal factor of " + what + " to a simplicial one");
}

void CholmodFactor::keepTrailing(const std::vector<int>& trailing) {
  Impl& f = *impl_;
  f.trailing_factor = linalg::trailingBlock(*f.L, static_cast<int>(trailing.size()));
  f.trailing_position.assign(static_cast<std::size_t>(f.n), -1);
  for (std::size_t k = 0; k < trailing.size(); ++k) f.trailing_position[static_cast<std::size_t>(trailing[k])] = static_cast<int>(k);
}

CholmodFactor::~CholmodFactor() = default;

Eigen::MatrixXd CholmodFactor::solve(const Eigen::MatrixXd& B, Workspace& workspace) const {
  const Eigen::Index n = impl_->n;
  if (B.rows() != n) throw std::invalid_argument("CholmodFactor::solve: right-hand side has the wrong number of rows");
  CholmodWorkspace& w = cholmodState(workspace);
  Eigen::MatrixXd X(n, B.cols());
  inChunks(isSupernodal(), B.cols(), [&](Eigen::Index c, Eigen::Index cols) {
    cholmod_dense b = denseView(B.data() + c * n, n, cols);  // B's columns c … c + cols − 1
    if (!cholmod_solve2(CHOLMOD_A, impl_->L, &b, nullptr, &w.X, nullptr, &w.Y, &w.E, &w.common))
      throw std::runtime_error("CHOLMOD solve failed (status " + std::to_string(w.common.status) + ")");
    const auto* x = static_cast<const double*>(w.X->x);
    for (Eigen::Index j = 0; j < cols; ++j)
      std::memcpy(X.col(c + j).data(), x + j * static_cast<Eigen::Index>(w.X->d), sizeof(double) * n);
  });
  return X;
}

Eigen::MatrixXd CholmodFactor::solveOnThreads(const Eigen::MatrixXd& B) const {
  const int part = isSupernodal() ? kSupernodalChunk : kChunk;
  if (takesTurns(isSupernodal()) || threadCount() == 1 || B.cols() <= part) return solve(B);
  std::vector<Workspace> workspaces;
  return solveInParts(B, part, workspaces);
}

Eigen::MatrixXd CholmodFactor::solveInParts(const Eigen::MatrixXd& B, int part, std::vector<Workspace>& workspaces) const {
  const int most = isSupernodal() ? kSupernodalChunk : kChunk;
  if (part < 1 || part > most)
    throw std::invalid_argument("CholmodFactor::solveInParts: part must be in [1, " + std::to_string(most) + "]");
  if (takesTurns(isSupernodal())) {  // one BLAS caller at a time (blasTurn): the whole block on this thread
    if (workspaces.empty()) workspaces.emplace_back();
    return solve(B, workspaces.front());
  }
  // A supernodal part is a chunk of solve(B) (its arithmetic depends on the columns solved together).
  if (isSupernodal()) part = kSupernodalChunk;
  Eigen::MatrixXd X(B.rows(), B.cols());
  onThreads(B.cols(), part, workspaces, [&](Eigen::Index begin, Eigen::Index width, Workspace& workspace) {
    X.middleCols(begin, width) = solve(B.middleCols(begin, width), workspace);
  });
  return X;
}

void CholmodFactor::onThreads(Eigen::Index columns, int part, std::vector<Workspace>& workspaces,
                              const std::function<void(Eigen::Index, Eigen::Index, Workspace&)>& body) const {
  const int parts = static_cast<int>((columns + part - 1) / part);
  const bool nested = detail::WorkerPool::insideRun();  // inside a parallel body: this thread alone
  const int threads = nested ? 1 : std::max(1, std::min(threadCount(), parts));
  while (static_cast<int>(workspaces.size()) < threads) workspaces.emplace_back();
  const auto run = [&](int index, int thread) {
    const Eigen::Index begin = static_cast<Eigen::Index>(index) * part;
    body(begin, std::min<Eigen::Index>(part, columns - begin), workspaces[static_cast<std::size_t>(thread)]);
  };
  if (nested) {
    for (int index = 0; index < parts; ++index) run(index, 0);
    return;
  }
  // A wrong row count is refused by the first part's solve, and parallelFor rethrows it.
  parallelFor(parts, threads, run);
}

bool CholmodFactor::condenses(const Eigen::SparseMatrix<double>& C) const {
  if (impl_->trailing_position.empty() || C.cols() != impl_->n) return false;
  for (Eigen::Index k = 0; k < C.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(C, k); it; ++it)
      if (it.value() != 0.0 && impl_->trailing_position[static_cast<std::size_t>(it.col())] < 0) return false;
  return true;
}

Eigen::SparseMatrix<double> CholmodFactor::trailingPart(const Eigen::SparseMatrix<double>& C, const char* caller) const {
  if (!condenses(C)) throw std::invalid_argument(std::string(caller) + ": C reads dofs outside the trailing ones");
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(C.nonZeros()));
  for (Eigen::Index k = 0; k < C.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(C, k); it; ++it)
      if (it.value() != 0.0)
        entries.emplace_back(impl_->trailing_position[static_cast<std::size_t>(it.col())], it.row(), it.value());
  Eigen::SparseMatrix<double> part(impl_->trailing_factor.rows(), C.rows());
  part.setFromTriplets(entries.begin(), entries.end());
  return part;
}

Eigen::MatrixXd CholmodFactor::condensed(const Eigen::SparseMatrix<double>& C) const {
  Eigen::MatrixXd Y = trailingPart(C, "CholmodFactor::condensed");  // C_Jᵀ, then L_JJ⁻¹ C_Jᵀ
  impl_->trailing_factor.triangularView<Eigen::Lower>().solveInPlace(Y);
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(C.rows(), C.rows());
  W.selfadjointView<Eigen::Lower>().rankUpdate(Y.transpose());
  return W.selfadjointView<Eigen::Lower>();
}

Eigen::MatrixXd CholmodFactor::solveFromTrailing(const Eigen::SparseMatrix<double>& R, const Eigen::MatrixXd& U) const {
  if (U.rows() != R.rows()) throw std::invalid_argument("CholmodFactor::solveFromTrailing: U must have R's rows");
  const Impl& f = *impl_;
  const Eigen::Index n = f.n, count = f.trailing_factor.rows();
  // (P Rᵀ U) on the trailing block, then L_JJ⁻¹ of it.
  Eigen::MatrixXd Y = trailingPart(R, "CholmodFactor::solveFromTrailing") * U;
  f.trailing_factor.triangularView<Eigen::Lower>().solveInPlace(Y);
  const auto* perm = static_cast<const int*>(f.L->Perm);
  Eigen::MatrixXd X(n, U.cols());
  const auto chunk = [&](Eigen::Index c, Eigen::Index cols, Workspace& workspace) {
    const auto turn = blasTurn(isSupernodal());  // with a serial BLAS, also the turn of f.own
    CholmodWorkspace& w = cholmodState(workspace);
    Eigen::MatrixXd y = Eigen::MatrixXd::Zero(n, cols);  // L⁻¹ P Rᵀ U: zero above the trailing block
    y.bottomRows(count) = Y.middleCols(c, cols);
    cholmod_dense b = denseView(y.data(), n, cols);
    if (!cholmod_solve2(CHOLMOD_Lt, f.L, &b, nullptr, &w.X, nullptr, &w.Y, &w.E, &w.common))
      throw std::runtime_error("CHOLMOD solve failed (status " + std::to_string(w.common.status) + ")");
    const auto* x = static_cast<const double*>(w.X->x);
    const Eigen::Index ld = static_cast<Eigen::Index>(w.X->d);
    for (Eigen::Index j = 0; j < cols; ++j)
      for (Eigen::Index k = 0; k < n; ++k) X(perm[k], c + j) = x[j * ld + k];  // x = Pᵀ (Lᵀ)⁻¹ y
  };
  const int part = isSupernodal() ? kSupernodalChunk : kChunk;
  if (takesTurns(isSupernodal())) {
    for (Eigen::Index c = 0; c < U.cols(); c += part) chunk(c, std::min<Eigen::Index>(part, U.cols() - c), f.own);
    return X;
  }
  std::vector<Workspace> workspaces;
  onThreads(U.cols(), part, workspaces, chunk);
  return X;
}

int CholmodFactor::size() const { return impl_->n; }
bool CholmodFactor::isSupernodal() const { return impl_->L->is_super != 0; }
double CholmodFactor::factorNonZeros() const { return impl_->common.lnz; }

}  // namespace stc
