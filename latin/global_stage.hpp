#pragma once
// LATIN global (linear) stage (docs/method.md §2): from ŝ find s ∈ A_d along λ − λ̂ = −k (v − v̂):
//   (K + Bᵀ k B) u(t_k) = f(t_k) + Bᵀ (λ̂(t_k) + k v̂(t_k))  for every k,   v = B u,
//   λ = λ̂ − k (v − v̂).
// The operator depends on neither time nor iteration: factorised once (CHOLMOD), then one
// multi-right-hand-side solve per iteration, by blocks of instants to bound memory. The blocks are
// independent: with threadCount() > 1 (src/core/threads.hpp) they are shared among threads, each
// with its own CHOLMOD workspace; every block's arithmetic is the same, so is the result.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "stcontact/latin/linear_stage.hpp"
#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/options/latin_options.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc::latin {

class GlobalStage : public LinearStage {
 public:
  /// Factorises K_ff + Bᵀ k B with k = problem.contact.search_direction.
  explicit GlobalStage(const Problem& problem, int block_size = LatinOptions{}.block_size);
  /// The same operator taken from `operators` (prepared there once for the run).
  GlobalStage(const Problem& problem, PreparedOperators& operators, int block_size = LatinOptions{}.block_size);

  /// s = global stage of ŝ (all instants). Adds m to the sparse-solve count.
  void solve(const InterfaceHistory& hat, InterfaceHistory& s) override { solve(hat, s, keep_ ? &u_ : nullptr); }
  /// The same; when `u` is given it receives the free displacements (n_free × m).
  void solve(const InterfaceHistory& hat, InterfaceHistory& s, Eigen::MatrixXd* u);
  /// Keeps the free displacements of every solve (n_free × m; `fas-aposteriori` builds its residual
  /// vectors from them): displacements().
  void keepDisplacements(bool keep) { keep_ = keep; }
  const Eigen::MatrixXd& displacements() const { return u_; }

  /// The operator K_ff + Bᵀ k B and its factor (the FAS coarse space and PGD use them).
  const Eigen::SparseMatrix<double>& matrix() const { return operator_->matrix; }
  const SpdSolver& factor() const override { return *operator_->factor; }
  long sparseSolves() const override { return sparse_solves_; }

 private:
  /// One block of instants k0 … k0 + count − 1, solved with `workspace`.
  void solveBlock(int k0, int count, const InterfaceHistory& hat, InterfaceHistory& s, Eigen::MatrixXd* u,
                  SpdSolver::Workspace& workspace) const;

  const Problem& problem_;
  std::shared_ptr<const SearchOperator> operator_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> B_rows_;  ///< B by rows: v = B u 4x faster (measured)
  int block_size_;
  std::vector<SpdSolver::Workspace> workspaces_;  ///< one per thread, grown on demand
  long sparse_solves_ = 0;
  bool keep_ = false;
  Eigen::MatrixXd u_;
};

}  // namespace stc::latin
