#include "stcontact/linalg/anderson.hpp"

#include <Eigen/Cholesky>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "stcontact/core/threads.hpp"

namespace stc {

AndersonMixing::AndersonMixing(int depth, Eigen::VectorXd row_weights)
    : depth_(depth), w_(std::move(row_weights)) {
  if (depth < 1) throw std::invalid_argument("AndersonMixing: depth must be >= 1");
  df_.resize(static_cast<size_t>(depth));
  slot_call_.assign(static_cast<size_t>(depth), 0);
  images_.resize(static_cast<size_t>(depth) + 1);
  gram_ = Eigen::MatrixXd::Zero(depth, depth);
}

void AndersonMixing::next(Eigen::MatrixXd& x, const Eigen::MatrixXd& image) {
  requireSizes(x, image);
  imageOf(call_ + 1) = image;  // F(x_j) joins the ring, in the buffer of F(x_{j−depth−1})
  advance(x);
}

void AndersonMixing::nextTaking(Eigen::MatrixXd& x, Eigen::MatrixXd& image) {
  requireSizes(x, image);
  imageOf(call_ + 1).swap(image);  // F(x_j) joins the ring; `image` gets the buffer of F(x_{j−depth−1})
  advance(x);
}

void AndersonMixing::requireSizes(const Eigen::MatrixXd& x, const Eigen::MatrixXd& image) const {
  if (w_.size() != x.rows() || image.rows() != x.rows() || image.cols() != x.cols())
    throw std::invalid_argument("AndersonMixing: iterate, image and weights differ in size");
}

void AndersonMixing::advance(Eigen::MatrixXd& x) {
  ++call_;
  const Eigen::MatrixXd& g = imageOf(call_);
  if (call_ == 0) {  // first call: a plain step
    last_f_ = w_.asDiagonal() * (g - x);
    last_norm_ = last_f_.norm();
    x = g;
    return;
  }
  newest_ = (newest_ + 1) % depth_;
  slot_call_[static_cast<size_t>(newest_)] = call_;
  const int held = std::min(count_ + 1, depth_);  // slots after this call, the newest included
  Eigen::VectorXd row, rhs;
  const double norm = std::sqrt(updateDifferences(x, held, row, rhs));
  // Safeguard (a restart, as in Zhang, O'Donoghue & Boyd, SIAM J. Sci. Comput. 42, 2020): a mixed
  // iterate whose residual exceeds its predecessor's is kept, but the differences are forgotten and
  // the next step is the plain one.
  const bool worse = mixed_ && norm > last_norm_;
  last_norm_ = norm;
  if (worse) {
    count_ = 0;
    newest_ = -1;
    mixed_ = false;
    ++restarts_;
    x = g;
    return;
  }
  count_ = held;
  for (int a = 0; a < count_; ++a) gram_(newest_, a) = gram_(a, newest_) = row[a];
  // Normal equations over the slots held: (ΔFᵀΔF + δ I) γ = ΔFᵀ f_j.
  const Eigen::MatrixXd G = gram_.topLeftCorner(count_, count_);
  const double shift = 1e-12 * G.diagonal().maxCoeff();
  mix(x, (G + shift * Eigen::MatrixXd::Identity(count_, count_)).ldlt().solve(rhs));
  mixed_ = true;
}

double AndersonMixing::updateDifferences(const Eigen::MatrixXd& x, int held, Eigen::VectorXd& row,
                                         Eigen::VectorXd& rhs) {
  const Eigen::Index rows = x.rows(), cols = x.cols();
  const Eigen::MatrixXd& image = imageOf(call_);
  Eigen::MatrixXd& df = df_[static_cast<size_t>(newest_)];
  df.resize(rows, cols);  // no reallocation once the ring is full
  // Per column: ‖f_j‖², ⟨ΔF_new, ΔF_a⟩ and ⟨ΔF_a, f_j⟩ (rows 0, 1 … held, held + 1 … 2 held), summed
  // below in column order, so that the sums do not depend on how the columns are split.
  Eigen::MatrixXd sums(2 * held + 1, cols);
  // One pass, column by column: f_j (weighted) replaces f_{j−1}, its difference is stored, and the
  // products are formed while the column is in cache (restrict pointers: the rows vectorise).
  const double* __restrict w = w_.data();
  parallelRanges(static_cast<int>(cols), threadCount(), [&](int begin, int end) {
    for (Eigen::Index c = begin; c < end; ++c) {
      const double* __restrict g = image.col(c).data();
      const double* __restrict xc = x.col(c).data();
      double* __restrict dfc = df.col(c).data();
      double* __restrict fc = last_f_.col(c).data();
      double squared = 0.0;
      for (Eigen::Index r = 0; r < rows; ++r) {
        const double f = w[r] * (g[r] - xc[r]);
        squared += f * f;
        dfc[r] = f - fc[r];
        fc[r] = f;
      }
      sums(0, c) = squared;
      for (int a = 0; a < held; ++a) {
        const double* __restrict da = df_[static_cast<size_t>(a)].col(c).data();
        double sum_new = 0.0, sum_f = 0.0;
        for (Eigen::Index r = 0; r < rows; ++r) {
          sum_new += dfc[r] * da[r];
          sum_f += da[r] * fc[r];
        }
        sums(1 + a, c) = sum_new;
        sums(1 + held + a, c) = sum_f;
      }
    }
  });
  row = Eigen::VectorXd::Zero(held);
  rhs = Eigen::VectorXd::Zero(held);
  double squared = 0.0;
  for (Eigen::Index c = 0; c < cols; ++c) {
    squared += sums(0, c);
    for (int a = 0; a < held; ++a) {
      row[a] += sums(1 + a, c);
      rhs[a] += sums(1 + held + a, c);
    }
  }
  return squared;
}

void AndersonMixing::mix(Eigen::MatrixXd& x, const Eigen::VectorXd& gamma) {
  // x_{j+1} = F(x_j) − ΔG γ, column by column, with ΔG_a = F(x_t) − F(x_{t−1}) read from the ring
  // of images (t the call that filled slot a).
  const Eigen::Index rows = x.rows();
  const Eigen::MatrixXd& image = imageOf(call_);
  parallelRanges(static_cast<int>(x.cols()), threadCount(), [&](int begin, int end) {
    for (Eigen::Index c = begin; c < end; ++c) {
      double* __restrict xc = x.col(c).data();
      const double* __restrict g = image.col(c).data();
      for (Eigen::Index r = 0; r < rows; ++r) xc[r] = g[r];
      for (int a = 0; a < count_; ++a) {
        const long t = slot_call_[static_cast<size_t>(a)];
        const double* __restrict now = imageOf(t).col(c).data();
        const double* __restrict before = imageOf(t - 1).col(c).data();
        const double ga = gamma[a];
        for (Eigen::Index r = 0; r < rows; ++r) xc[r] -= ga * (now[r] - before[r]);
      }
    }
  });
}

}  // namespace stc
