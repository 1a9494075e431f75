#pragma once
// Tall columns kept as the blocks they were appended in, so that appending never copies what is
// held: the storage is the columns themselves (ColumnStore, pgd/column_store.hpp, keeps one matrix
// and doubles it, holding both while it grows: up to 3× the columns). For the responses X of the
// separated global stage (pgd/response_basis.hpp), n_free rows: at 592k dofs that copy alone was
// the difference between keeping X within its bytes and releasing it (docs/scale.md). Products read
// the blocks in turn: X M = Σ_b X_b M_b, with M_b the rows of M of block b.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <algorithm>
#include <stdexcept>
#include <vector>

namespace stc::pgd {

class ColumnBlocks {
 public:
  explicit ColumnBlocks(Eigen::Index rows = 0) : rows_(rows) {}

  Eigen::Index rows() const { return rows_; }
  Eigen::Index cols() const { return cols_; }
  /// Bytes held: rows × columns doubles, nothing spare.
  double bytes() const { return static_cast<double>(sizeof(double)) * static_cast<double>(rows_) * cols_; }

  /// Takes `block` (rows() × b) as the next b columns; no copy.
  void append(Eigen::MatrixXd&& block) {
    if (block.rows() != rows_) throw std::invalid_argument("ColumnBlocks::append: a block of other rows");
    if (block.cols() == 0) return;
    cols_ += block.cols();
    blocks_.push_back(std::move(block));
  }

  /// into += X_p M (into: rows() × k) for the first p = M.rows() columns.
  void addProduct(const Eigen::Ref<const Eigen::MatrixXd>& M, Eigen::MatrixXd& into) const {
    forBlocksOf(M.rows(), [&](const Eigen::MatrixXd& X, Eigen::Index first, Eigen::Index width) {
      into.noalias() += X.leftCols(width) * M.middleRows(first, width);
    });
  }

  /// X_p M (rows() × k) for the first p = M.rows() columns.
  Eigen::MatrixXd times(const Eigen::Ref<const Eigen::MatrixXd>& M) const {
    Eigen::MatrixXd product = Eigen::MatrixXd::Zero(rows_, M.cols());
    addProduct(M, product);
    return product;
  }

  /// S X_p (S.rows() × p) for the first p columns.
  Eigen::MatrixXd rowsOf(const Eigen::SparseMatrix<double>& S, Eigen::Index p) const {
    Eigen::MatrixXd product(S.rows(), p);
    forBlocksOf(p, [&](const Eigen::MatrixXd& X, Eigen::Index first, Eigen::Index width) {
      product.middleCols(first, width) = S * X.leftCols(width);
    });
    return product;
  }

  /// The columns as one matrix (a copy).
  Eigen::MatrixXd gathered() const {
    Eigen::MatrixXd all(rows_, cols_);
    forBlocksOf(cols_, [&](const Eigen::MatrixXd& X, Eigen::Index first, Eigen::Index width) {
      all.middleCols(first, width) = X.leftCols(width);
    });
    return all;
  }

 private:
  /// Calls visit(block, first column, width) for the blocks holding the first p columns.
  template <class Visit>
  void forBlocksOf(Eigen::Index p, Visit&& visit) const {
    if (p > cols_) throw std::out_of_range("ColumnBlocks: more columns asked for than held");
    Eigen::Index first = 0;
    for (const Eigen::MatrixXd& block : blocks_) {
      if (first >= p) break;
      const Eigen::Index width = std::min(block.cols(), p - first);
      visit(block, first, width);
      first += width;
    }
  }

  Eigen::Index rows_;
  Eigen::Index cols_ = 0;
  std::vector<Eigen::MatrixXd> blocks_;
};

}  // namespace stc::pgd
