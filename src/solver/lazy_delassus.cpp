#include "src/solver/lazy_delassus.hpp"

#include <algorithm>

namespace stc {

LazyDelassus::LazyDelassus(const Problem& problem, const SpdFactor& stiffness_free)
    : B_(problem.contact.B),
      Bt_(problem.contact.B.transpose()),
      factor_(stiffness_free),
      d_(problem.contact.dimension),
      held_rows_(problem.contact.held_rows),
      slot_(problem.contact.size(), -1) {}

void LazyDelassus::ensure(const std::vector<int>& nodes) {
  std::vector<int> missing;
  for (int j : nodes)
    if (slot_[j] < 0 && std::find(missing.begin(), missing.end(), j) == missing.end()) missing.push_back(j);
  if (missing.empty()) return;
  const auto& B = B_;
  const int needed = (count_ + static_cast<int>(missing.size())) * d_;
  if (needed > columns_.cols())  // grow by doubling: amortised copies
    columns_.conservativeResize(B.rows(), std::max<Eigen::Index>(needed, 2 * columns_.cols()));
  Eigen::MatrixXd rhs(B.cols(), d_ * static_cast<Eigen::Index>(missing.size()));
  for (std::size_t p = 0; p < missing.size(); ++p)
    for (int a = 0; a < d_; ++a) rhs.col(static_cast<Eigen::Index>(p) * d_ + a) = Bt_.col(d_ * missing[p] + a);
  const Eigen::MatrixXd w = B * factor_.solve(rhs);
  for (std::size_t p = 0; p < missing.size(); ++p) {
    slot_[missing[p]] = count_;
    columns_.middleCols(static_cast<Eigen::Index>(count_) * d_, d_) = w.middleCols(static_cast<Eigen::Index>(p) * d_, d_);
    ++count_;
  }
  // Held rows: the compliance of giveHeldRowsCompliance (condensed_interface.hpp).
  for (int r : held_rows_)
    if (const int j = r / d_; std::find(missing.begin(), missing.end(), j) != missing.end())
      columns_(r, static_cast<Eigen::Index>(slot_[j]) * d_ + r % d_) = entry(d_ * j, j, 0);
}

Eigen::MatrixXd freeInterfaceResponse(const Problem& problem, const SpdFactor& stiffness_free) {
  const auto& B = problem.contact.B;
  Eigen::MatrixXd v0 = Eigen::MatrixXd::Zero(B.rows(), problem.numSteps());
  for (const auto& term : problem.loads) {
    const Eigen::VectorXd w = B * stiffness_free.solve(term.free_force);
    v0.noalias() += w * Eigen::Map<const Eigen::RowVectorXd>(term.values.data(), problem.numSteps());
  }
  return v0;
}

}  // namespace stc
