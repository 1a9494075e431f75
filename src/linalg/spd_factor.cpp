#include "stcontact/linalg/spd_factor.hpp"

#include <Eigen/CholmodSupport>
#include <algorithm>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/threads.hpp"

namespace stc {

struct SpdFactor::Workspace::Impl {
  cholmod_common common;
  cholmod_dense *X = nullptr, *Y = nullptr, *E = nullptr;  ///< cholmod_solve2's solution and buffers
  Impl() {
    cholmod_start(&common);
    common.print = 0;  // failures are thrown, not printed
  }
  ~Impl() {
    cholmod_free_dense(&X, &common);
    cholmod_free_dense(&Y, &common);
    cholmod_free_dense(&E, &common);
    cholmod_finish(&common);
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
};

SpdFactor::Workspace::Workspace() : impl_(std::make_unique<Impl>()) {}
SpdFactor::Workspace::~Workspace() = default;
SpdFactor::Workspace::Workspace(Workspace&&) noexcept = default;
SpdFactor::Workspace& SpdFactor::Workspace::operator=(Workspace&&) noexcept = default;

// Solves are simplicial LLᵀ (the settings of Eigen's CholmodSimplicialLLT). Not supernodal: the
// supernodal solve calls the BLAS (dtrsm, dgemm), and Debian's serial OpenBLAS 0.3.21 returns wrong
// columns when two threads call it at once (measured: ~2% of concurrent 16-column solves; none with
// the reference BLAS); the simplicial solve is plain C, and on these 2D meshes it is not slower
// (thread CPU time per 201 right-hand sides, chunks of 16: 2.3–2.6 vs 2.6–2.7 ms at n = 1088,
// 7.1–8.2 vs 9–11 ms at n = 2560, 19–22 vs 18–23 ms at n = 5700; docs/threads.md).
// The factorisation is left to CHOLMOD's own choice (CHOLMOD_AUTO: supernodal when the flop count
// per factor entry reaches common.supernodal_switch = 40, which the 2D meshes do not and 3D meshes
// do): a supernodal factor is converted to a simplicial one before any solve
// (cholmod_change_factor), and supernodal factorisations, the only BLAS calls, run one at a time.
// Measured on the half-ball (dimension = 3, divisions 16, 52272 free dofs): 24 s simplicial.
struct SpdFactor::Impl {
  cholmod_common common;
  cholmod_factor* L = nullptr;
  Workspace own;  ///< for solve(B) without a workspace
  int n = 0;
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

SpdFactor::SpdFactor(const Eigen::SparseMatrix<double>& A, const std::string& what)
    : impl_(std::make_unique<Impl>()) {
  impl_->n = static_cast<int>(A.rows());
  cholmod_sparse view = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
  impl_->L = cholmod_analyze(&view, &impl_->common);
  double beta[2] = {0.0, 0.0};
  if (impl_->L && impl_->L->is_super) {
    static std::mutex blas;  // see above: one BLAS caller at a time
    const std::lock_guard<std::mutex> lock(blas);
    cholmod_factorize_p(&view, beta, nullptr, 0, impl_->L, &impl_->common);
  } else if (impl_->L) {
    cholmod_factorize_p(&view, beta, nullptr, 0, impl_->L, &impl_->common);
  }
  if (!impl_->L || impl_->L->minor != impl_->L->n)
    throw InputError(what + " is not positive definite (do the Dirichlet conditions fix every rigid-body motion?)");
  if (impl_->L->is_super && !cholmod_change_factor(CHOLMOD_REAL, 1, 0, 1, 1, impl_->L, &impl_->common))
    throw std::runtime_error("CHOLMOD could not convert the supernodal factor of " + what + " to a simplicial one");
}

SpdFactor::~SpdFactor() = default;
SpdFactor::SpdFactor(SpdFactor&&) noexcept = default;
SpdFactor& SpdFactor::operator=(SpdFactor&&) noexcept = default;

Eigen::MatrixXd SpdFactor::solve(const Eigen::MatrixXd& B, Workspace& workspace) const {
  const Eigen::Index n = impl_->n;
  if (B.rows() != n) throw std::invalid_argument("SpdFactor::solve: right-hand side has the wrong number of rows");
  Workspace::Impl& w = *workspace.impl_;
  Eigen::MatrixXd X(n, B.cols());
  for (Eigen::Index c = 0; c < B.cols(); c += kChunk) {
    const Eigen::Index cols = std::min<Eigen::Index>(kChunk, B.cols() - c);
    cholmod_dense b{};  // a view of B's columns c … c + cols − 1 (column-major, leading dimension n)
    b.nrow = n;
    b.ncol = cols;
    b.nzmax = n * cols;
    b.d = n;
    b.x = const_cast<double*>(B.data() + c * n);
    b.xtype = CHOLMOD_REAL;
    b.dtype = CHOLMOD_DOUBLE;
    if (!cholmod_solve2(CHOLMOD_A, impl_->L, &b, nullptr, &w.X, nullptr, &w.Y, &w.E, &w.common))
      throw std::runtime_error("CHOLMOD solve failed (status " + std::to_string(w.common.status) + ")");
    const auto* x = static_cast<const double*>(w.X->x);
    for (Eigen::Index j = 0; j < cols; ++j)
      std::memcpy(X.col(c + j).data(), x + j * static_cast<Eigen::Index>(w.X->d), sizeof(double) * n);
  }
  return X;
}

Eigen::MatrixXd SpdFactor::solve(const Eigen::MatrixXd& B) const { return solve(B, impl_->own); }

Eigen::MatrixXd SpdFactor::solveOnThreads(const Eigen::MatrixXd& B) const {
  if (threadCount() == 1 || B.cols() <= kChunk) return solve(B);
  std::vector<Workspace> workspaces;
  return solveInParts(B, kChunk, workspaces);
}

Eigen::MatrixXd SpdFactor::solveInParts(const Eigen::MatrixXd& B, int part, std::vector<Workspace>& workspaces) const {
  if (part < 1 || part > kChunk)
    throw std::invalid_argument("SpdFactor::solveInParts: part must be in [1, " + std::to_string(kChunk) + "]");
  const int parts = static_cast<int>((B.cols() + part - 1) / part);
  const int threads = std::max(1, std::min(threadCount(), parts));
  while (static_cast<int>(workspaces.size()) < threads) workspaces.emplace_back();
  // A wrong row count is refused by solve(B, workspace) in the first part, and parallelFor rethrows it.
  Eigen::MatrixXd X(B.rows(), B.cols());
  parallelFor(parts, threads, [&](int index, int thread) {
    const Eigen::Index begin = static_cast<Eigen::Index>(index) * part;
    const Eigen::Index width = std::min<Eigen::Index>(part, B.cols() - begin);
    X.middleCols(begin, width) = solve(B.middleCols(begin, width), workspaces[static_cast<std::size_t>(thread)]);
  });
  return X;
}
Eigen::VectorXd SpdFactor::solve(const Eigen::VectorXd& b) const {
  return solve(Eigen::MatrixXd(b), impl_->own).col(0);
}
int SpdFactor::size() const { return impl_->n; }
double SpdFactor::factorNonZeros() const { return impl_->common.lnz; }

}  // namespace stc
