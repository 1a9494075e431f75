#include "src/linalg/anderson.hpp"

#include <Eigen/Cholesky>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace stc {

AndersonMixing::AndersonMixing(int depth, Eigen::VectorXd row_weights)
    : depth_(depth), w_(std::move(row_weights)), df_(depth > 0 ? depth : 0), dg_(depth > 0 ? depth : 0) {
  if (depth < 1) throw std::invalid_argument("AndersonMixing: depth must be >= 1");
  gram_ = Eigen::MatrixXd::Zero(depth, depth);
}

void AndersonMixing::next(Eigen::MatrixXd& x, const Eigen::MatrixXd& image) {
  const Eigen::Index rows = x.rows(), cols = x.cols();
  if (w_.size() != rows || image.rows() != rows || image.cols() != cols)
    throw std::invalid_argument("AndersonMixing: iterate, image and weights differ in size");
  if (last_f_.size() == 0) {  // first call: a plain step
    last_f_ = w_.asDiagonal() * (image - x);
    last_norm_ = last_f_.norm();
    last_image_ = image;
    x = image;
    return;
  }
  newest_ = (newest_ + 1) % depth_;
  const int held = std::min(count_ + 1, depth_);  // slots after this call, the newest included
  Eigen::MatrixXd& df = df_[static_cast<size_t>(newest_)];
  Eigen::MatrixXd& dg = dg_[static_cast<size_t>(newest_)];
  df.resize(rows, cols);  // no reallocation once the ring is full
  dg.resize(rows, cols);
  // One pass, column by column: f_j (weighted) replaces f_{j−1}, F(x_j) replaces F(x_{j−1}), their
  // differences are stored, and the products the least-squares problem needs, ⟨ΔF_new, ΔF_a⟩ and
  // ⟨ΔF_a, f_j⟩, are summed while the column is in cache (restrict pointers: the rows vectorise).
  const double* __restrict w = w_.data();
  double squared = 0.0;
  Eigen::VectorXd row = Eigen::VectorXd::Zero(held), rhs = Eigen::VectorXd::Zero(held);
  for (Eigen::Index c = 0; c < cols; ++c) {
    const double* __restrict g = image.col(c).data();
    const double* __restrict xc = x.col(c).data();
    double* __restrict dfc = df.col(c).data();
    double* __restrict dgc = dg.col(c).data();
    double* __restrict fc = last_f_.col(c).data();
    double* __restrict gc = last_image_.col(c).data();
    for (Eigen::Index r = 0; r < rows; ++r) {
      const double f = w[r] * (g[r] - xc[r]);
      squared += f * f;
      dfc[r] = f - fc[r];
      dgc[r] = g[r] - gc[r];
      fc[r] = f;
      gc[r] = g[r];
    }
    for (int a = 0; a < held; ++a) {
      const double* __restrict da = df_[static_cast<size_t>(a)].col(c).data();
      double sum_new = 0.0, sum_f = 0.0;
      for (Eigen::Index r = 0; r < rows; ++r) {
        sum_new += dfc[r] * da[r];
        sum_f += da[r] * fc[r];
      }
      row[a] += sum_new;
      rhs[a] += sum_f;
    }
  }
  // Safeguard (a restart, as in Zhang, O'Donoghue & Boyd, SIAM J. Sci. Comput. 42, 2020): a mixed
  // iterate whose residual exceeds its predecessor's is kept, but the differences are forgotten and
  // the next step is the plain one.
  const double norm = std::sqrt(squared);
  const bool worse = mixed_ && norm > last_norm_;
  last_norm_ = norm;
  if (worse) {
    count_ = 0;
    newest_ = -1;
    mixed_ = false;
    ++restarts_;
    x = image;
    return;
  }
  count_ = held;
  for (int a = 0; a < count_; ++a) gram_(newest_, a) = gram_(a, newest_) = row[a];
  // Normal equations over the slots held: (ΔFᵀΔF + δ I) γ = ΔFᵀ f_j.
  const Eigen::MatrixXd G = gram_.topLeftCorner(count_, count_);
  const double shift = 1e-12 * G.diagonal().maxCoeff();
  const Eigen::VectorXd gamma = (G + shift * Eigen::MatrixXd::Identity(count_, count_)).ldlt().solve(rhs);
  // x_{j+1} = F(x_j) − ΔG γ, column by column.
  for (Eigen::Index c = 0; c < cols; ++c) {
    double* __restrict xc = x.col(c).data();
    const double* __restrict g = image.col(c).data();
    for (Eigen::Index r = 0; r < rows; ++r) xc[r] = g[r];
    for (int a = 0; a < count_; ++a) {
      const double* __restrict da = dg_[static_cast<size_t>(a)].col(c).data();
      const double ga = gamma[a];
      for (Eigen::Index r = 0; r < rows; ++r) xc[r] -= ga * da[r];
    }
  }
  mixed_ = true;
}

}  // namespace stc
