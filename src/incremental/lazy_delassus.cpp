#include "stcontact/incremental/lazy_delassus.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "stcontact/incremental/condensed_interface.hpp"

namespace stc {

LazyDelassus::LazyDelassus(const Problem& problem, const SpdSolver& stiffness_free, double chunk_bytes)
    : B_(problem.contact.B),
      Bt_(problem.contact.B.transpose()),
      factor_(&stiffness_free),
      d_(problem.contact.dimension),
      chunk_bytes_(chunk_bytes),
      held_rows_(problem.contact.held_rows),
      slot_(problem.contact.size(), -1) {}

LazyDelassus::LazyDelassus(const Problem& problem, Eigen::MatrixXd W)
    : B_(problem.contact.B),
      factor_(nullptr),
      d_(problem.contact.dimension),
      chunk_bytes_(kChunkBytes),
      held_rows_(problem.contact.held_rows),
      slot_(problem.contact.size()),
      columns_(std::move(W)),
      count_(problem.contact.size()) {
  if (columns_.rows() != B_.rows() || columns_.cols() != B_.rows())
    throw std::invalid_argument("LazyDelassus: W must be d n_C × d n_C");
  for (int j = 0; j < count_; ++j) slot_[static_cast<std::size_t>(j)] = j;
  giveHeldRowsCompliance(problem.contact, columns_);
}

void LazyDelassus::ensure(const std::vector<int>& nodes, const ChunkDone& after_chunk) {
  std::vector<int> missing;
  for (int j : nodes)
    if (slot_[j] < 0 && std::find(missing.begin(), missing.end(), j) == missing.end()) missing.push_back(j);
  if (missing.empty()) return;
  reserve(count_ + static_cast<int>(missing.size()));
  const auto chunk = static_cast<std::size_t>(chunkNodes());
  for (std::size_t first = 0; first < missing.size(); first += chunk) {
    const std::size_t last = std::min(missing.size(), first + chunk);
    solveColumns({missing.begin() + static_cast<std::ptrdiff_t>(first), missing.begin() + static_cast<std::ptrdiff_t>(last)});
    if (after_chunk) after_chunk(static_cast<int>(last), static_cast<int>(missing.size()));
  }
}

// Capacity for `nodes` nodes: doubling (amortised copies), never beyond the d n_C columns of W.
void LazyDelassus::reserve(int nodes) {
  const Eigen::Index needed = static_cast<Eigen::Index>(nodes) * d_;
  if (needed <= columns_.cols()) return;
  const Eigen::Index whole = static_cast<Eigen::Index>(slot_.size()) * d_;
  columns_.conservativeResize(B_.rows(), std::min(whole, std::max(needed, 2 * columns_.cols())));
}

// Nodes per multi-right-hand-side solve: the dense right-hand side (n_free × d per node) stays below
// chunk_bytes_, whatever the number of nodes asked for at once.
int LazyDelassus::chunkNodes() const {
  const double bytes_per_node = 8.0 * static_cast<double>(Bt_.rows()) * d_;
  return std::max(1, static_cast<int>(chunk_bytes_ / bytes_per_node));
}

// W(:, columns of `nodes`) = B K⁻¹ Bᵀ(:, columns of `nodes`), stored in the next free slots.
void LazyDelassus::solveColumns(const std::vector<int>& nodes) {
  Eigen::MatrixXd rhs(Bt_.rows(), d_ * static_cast<Eigen::Index>(nodes.size()));
  for (std::size_t p = 0; p < nodes.size(); ++p)
    for (int a = 0; a < d_; ++a) rhs.col(static_cast<Eigen::Index>(p) * d_ + a) = Bt_.col(d_ * nodes[p] + a);
  const Eigen::MatrixXd w = B_ * factor_->solveOnThreads(rhs);
  solves_ += static_cast<int>(rhs.cols());
  for (std::size_t p = 0; p < nodes.size(); ++p) {
    slot_[nodes[p]] = count_;
    columns_.middleCols(static_cast<Eigen::Index>(count_) * d_, d_) = w.middleCols(static_cast<Eigen::Index>(p) * d_, d_);
    ++count_;
  }
  // Held rows: the compliance of giveHeldRowsCompliance (condensed_interface.hpp).
  for (int r : held_rows_)
    if (const int j = r / d_; std::find(nodes.begin(), nodes.end(), j) != nodes.end())
      columns_(r, static_cast<Eigen::Index>(slot_[j]) * d_ + r % d_) = entry(d_ * j, j, 0);
}

Eigen::MatrixXd freeInterfaceResponse(const Problem& problem, const SpdSolver& stiffness_free) {
  const auto& B = problem.contact.B;
  Eigen::MatrixXd v0 = Eigen::MatrixXd::Zero(B.rows(), problem.numSteps());
  for (const auto& term : problem.loads) {
    const Eigen::VectorXd w = B * stiffness_free.solve(term.free_force);
    v0.noalias() += w * Eigen::Map<const Eigen::RowVectorXd>(term.values.data(), problem.numSteps());
  }
  return v0;
}

std::string LazyDelassus::remark(int contact_nodes) const {
  std::ostringstream note;
  note << "Delassus columns of " << nodesComputed() << " of " << contact_nodes << " contact nodes (" << bytes() / 1e6
       << " MB)";
  return note.str();
}

}  // namespace stc
