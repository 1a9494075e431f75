#pragma once
// Columns appended in blocks to a matrix with spare capacity (doubling), so that appending b
// columns to p costs O(rows · b) amortised instead of a copy of all p (Eigen's conservativeResize
// copies the whole matrix every time). The columns held are a view of the storage.
#include <Eigen/Core>
#include <algorithm>

namespace stc::pgd {

class ColumnStore {
 public:
  using View = Eigen::Block<const Eigen::MatrixXd, Eigen::Dynamic, Eigen::Dynamic, true>;
  explicit ColumnStore(Eigen::Index rows = 0) : data_(rows, 0) {}

  Eigen::Index rows() const { return data_.rows(); }
  Eigen::Index cols() const { return cols_; }
  /// The columns held (a view: valid until the next append).
  View view() const { return data_.leftCols(cols_); }

  void append(const Eigen::Ref<const Eigen::MatrixXd>& block) {
    const Eigen::Index needed = cols_ + block.cols();
    if (needed > data_.cols()) data_.conservativeResize(Eigen::NoChange, grownCapacity(needed));
    data_.middleCols(cols_, block.cols()) = block;
    cols_ = needed;
  }

 private:
  Eigen::Index grownCapacity(Eigen::Index needed) const { return std::max(needed, 2 * data_.cols()); }

  Eigen::MatrixXd data_;
  Eigen::Index cols_ = 0;
};

}  // namespace stc::pgd
