#pragma once
// The columns of the Delassus operator W = B K⁻¹ Bᵀ (src/incremental/condensed_interface.hpp), computed
// only for the contact nodes that need them, the first time they do: node j's d columns
// W(:, d j … d j + d − 1) = B K⁻¹ B(d j … d j + d − 1, :)ᵀ take d sparse solves. The incremental
// solver needs the columns of the nodes that carry a force (v = v_0 + W λ) and of the closed ones
// (the Newton system), never those of the nodes that stay open: memory d n_C × d n_ever-closed
// instead of the dense (d n_C)², and as many sparse solves as nodes ever closed (times d).
#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/problem/problem.hpp"

namespace stc {

class LazyDelassus {
 public:
  /// Bound on each dense block of one solve (its right-hand side, and its solution of the same
  /// size: n_free × d per node): 128 MiB. Asking for every node of a large 3D interface at once (the
  /// error measure does, when a LATIN iterate loads them all; half_ball divisions 16: 2 × 3.8 GB as
  /// one block) then costs the columns alone.
  static constexpr double kChunkBytes = 128.0 * 1024 * 1024;

  LazyDelassus(const Problem& problem, const SpdSolver& stiffness_free, double chunk_bytes = kChunkBytes);
  /// Every node's columns given: W (d n_C × d n_C) of `problem`'s interface, e.g. from the trailing
  /// block of the factor (SpdSolver::condensed); held rows get their compliance here. ensure() then
  /// never solves.
  LazyDelassus(const Problem& problem, Eigen::MatrixXd W);

  /// After each chunk of ensure(): how many of the missing nodes have their columns, of how many.
  using ChunkDone = std::function<void(int nodes_done, int nodes_missing)>;

  /// Computes the columns of the nodes of `nodes` that do not have them yet (one multi-right-hand-
  /// side solve per chunk of them, chunkNodes()), calling `after_chunk` after each; a held row gets
  /// the compliance of giveHeldRowsCompliance (condensed_interface.hpp).
  void ensure(const std::vector<int>& nodes, const ChunkDone& after_chunk = {});
  bool has(int node) const { return slot_[node] >= 0; }
  /// W(:, d node + a), a = 0 … d − 1 (the node's columns must exist).
  auto column(int node, int a) const { return columns_.col(static_cast<Eigen::Index>(slot_[node]) * d_ + a); }
  /// W(r, d node + a).
  double entry(int r, int node, int a) const { return columns_(r, static_cast<Eigen::Index>(slot_[node]) * d_ + a); }
  int nodesComputed() const { return count_; }
  int sparseSolves() const { return solves_; }  ///< none for columns given whole
  /// Bytes held by the columns.
  double bytes() const { return 8.0 * static_cast<double>(columns_.rows()) * d_ * count_; }
  /// The summary's remark: "Delassus columns of N of n contact nodes (M MB)", n = `contact_nodes`.
  std::string remark(int contact_nodes) const;

 private:
  void reserve(int nodes);
  int chunkNodes() const;
  void solveColumns(const std::vector<int>& nodes);

  const Eigen::SparseMatrix<double>& B_;
  const Eigen::SparseMatrix<double> Bt_;  // Bᵀ, its columns the right-hand sides of a node
  const SpdSolver* factor_;  // null when every column was given
  int d_;
  double chunk_bytes_;
  std::vector<int> held_rows_;  // ContactInterface::held_rows, given a compliance when their node's columns come
  std::vector<int> slot_;    // per contact node: its block among the columns, −1 if not computed
  Eigen::MatrixXd columns_;  // d n_C × d capacity
  int count_ = 0;
  int solves_ = 0;
};

/// v_0 = B K⁻¹ f(t_k) for every instant (d n_C × m), one sparse solve per load term.
Eigen::MatrixXd freeInterfaceResponse(const Problem& problem, const SpdSolver& stiffness_free);

}  // namespace stc
