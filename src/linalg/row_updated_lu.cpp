#include "stcontact/linalg/row_updated_lu.hpp"

#include <algorithm>
#include <stdexcept>

namespace stc::linalg {

RowUpdatedLu::RowUpdatedLu(double max_share) : max_share_(max_share) {
  if (!(max_share >= 0.0 && max_share <= 1.0)) throw std::invalid_argument("RowUpdatedLu: max_share must be in [0, 1]");
}

Eigen::VectorXd RowUpdatedLu::solve(const std::vector<int>& key, const Eigen::MatrixXd& M, const Eigen::VectorXd& b) {
  requireSizes(M, b);
  Eigen::VectorXd x;
  if (updatable(key, M) && update(M, b, changedRows(M), x)) return x;
  return factorise(key, M, b);
}

Eigen::VectorXd RowUpdatedLu::solve(const std::vector<int>& key, const Eigen::MatrixXd& M, const Eigen::VectorXd& b,
                                    const std::vector<Eigen::Index>& changed) {
  requireSizes(M, b);
  for (Eigen::Index i : changed)
    if (i < 0 || i >= M.rows()) throw std::invalid_argument("RowUpdatedLu: a changed row is outside M");
  Eigen::VectorXd x;
  if (updatable(key, M) && update(M, b, changedRowsAmong(M, changed), x)) return x;
  return factorise(key, M, b);
}

void RowUpdatedLu::requireSizes(const Eigen::MatrixXd& M, const Eigen::VectorXd& b) {
  if (M.rows() != M.cols() || M.rows() != b.size())
    throw std::invalid_argument("RowUpdatedLu: M must be square, b of its size");
}

bool RowUpdatedLu::updatable(const std::vector<int>& key, const Eigen::MatrixXd& M) const {
  return factorised_ && key == key_ && M.rows() == M0_.rows();
}

Eigen::VectorXd RowUpdatedLu::factorise(const std::vector<int>& key, const Eigen::MatrixXd& M,
                                        const Eigen::VectorXd& b) {
  key_ = key;
  M0_ = M;
  lu_.compute(M0_);
  factorised_ = true;
  column_of_.assign(static_cast<std::size_t>(M.rows()), -1);
  differing_.clear();
  stored_ = 0;
  ++counts_.factorisations;
  return lu_.solve(b);
}

// The rows where M differs from M₀ (any entry, compared exactly).
std::vector<Eigen::Index> RowUpdatedLu::changedRows(const Eigen::MatrixXd& M) const {
  Eigen::VectorXd difference = Eigen::VectorXd::Zero(M.rows());  // Σ_j |M − M₀|(i, j), NaN kept
  for (Eigen::Index j = 0; j < M.cols(); ++j) difference += (M.col(j) - M0_.col(j)).cwiseAbs();
  std::vector<Eigen::Index> rows;
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    if (difference[i] != 0.0) rows.push_back(i);
  return rows;
}

// The rows of changedRows(M) are among `changed` and the rows that differed at the previous call
// (the others are those of M₀): the same test, Σ_j |M − M₀|(i, j) ≠ 0 (NaN kept), on those alone.
std::vector<Eigen::Index> RowUpdatedLu::changedRowsAmong(const Eigen::MatrixXd& M,
                                                         const std::vector<Eigen::Index>& changed) const {
  std::vector<Eigen::Index> candidates = differing_;
  candidates.insert(candidates.end(), changed.begin(), changed.end());
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  std::vector<Eigen::Index> rows;
  for (Eigen::Index i : candidates)
    if ((M.row(i) - M0_.row(i)).cwiseAbs().sum() != 0.0) rows.push_back(i);
  return rows;
}

// M₀⁻¹ e_j for the rows not yet solved for, in one block solve.
void RowUpdatedLu::ensureColumns(const std::vector<Eigen::Index>& rows) {
  std::vector<Eigen::Index> missing;
  for (Eigen::Index j : rows)
    if (column_of_[static_cast<std::size_t>(j)] < 0) missing.push_back(j);
  if (missing.empty()) return;
  const Eigen::Index n = M0_.rows(), k = static_cast<Eigen::Index>(missing.size());
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n, k);
  for (Eigen::Index c = 0; c < k; ++c) E(missing[static_cast<std::size_t>(c)], c) = 1.0;
  if (columns_.rows() != n || columns_.cols() < stored_ + k)  // each row once per factor: n at most
    columns_.conservativeResize(n, std::min(n, std::max(2 * (stored_ + k), Eigen::Index(8))));
  columns_.middleCols(stored_, k) = lu_.solve(E);
  for (Eigen::Index c = 0; c < k; ++c)
    column_of_[static_cast<std::size_t>(missing[static_cast<std::size_t>(c)])] = stored_ + c;
  stored_ += k;
}

bool RowUpdatedLu::update(const Eigen::MatrixXd& M, const Eigen::VectorXd& b, const std::vector<Eigen::Index>& rows,
                          Eigen::VectorXd& x) {
  const auto r = static_cast<Eigen::Index>(rows.size());
  if (static_cast<double>(r) > max_share_ * static_cast<double>(M.rows())) return false;
  x = lu_.solve(b);  // y = M₀⁻¹ b
  if (r > 0) {
    ensureColumns(rows);
    Eigen::MatrixXd Z(M.rows(), r), D(r, M.cols());
    for (Eigen::Index c = 0; c < r; ++c) {
      const Eigen::Index i = rows[static_cast<std::size_t>(c)];
      Z.col(c) = columns_.col(column_of_[static_cast<std::size_t>(i)]);
      D.row(c) = M.row(i) - M0_.row(i);
    }
    Eigen::MatrixXd capacitance = D * Z;
    capacitance.diagonal().array() += 1.0;
    const Eigen::VectorXd Dy = D * x;
    x.noalias() -= Z * capacitance.partialPivLu().solve(Dy);
  }
  const bool accepted = x.allFinite() && (b - M * x).norm() <= kResidualBound * b.norm();
  ++(accepted ? counts_.updates : counts_.rejected);
  if (accepted) differing_ = rows;
  return accepted;
}

}  // namespace stc::linalg
