#include "stcontact/pgd/energy_factor.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stc::pgd {
namespace {

// Grows a square storage to hold at least n × n (capacity doubling; entries kept).
void reserve(Eigen::MatrixXd& storage, Eigen::Index n) {
  if (n <= storage.cols()) return;
  const Eigen::Index capacity = std::max<Eigen::Index>(n, 2 * storage.cols());
  storage.conservativeResize(capacity, capacity);
}

}  // namespace

void EnergyFactor::append(const Eigen::VectorXd& products) {
  const int j = size_, r = rank();
  if (products.size() != j + 1) throw std::invalid_argument("EnergyFactor::append: needs size() + 1 products");
  reserve(R_, j + 1);
  reserve(RK_, r + 1);
  // Coefficients of φ_j on Φ̂: R_Kᵀ y = M(K, j) (a triangular solve).
  Eigen::VectorXd y(r);
  for (int i = 0; i < r; ++i) y[i] = products[kept_[static_cast<size_t>(i)]];
  RK_.topLeftCorner(r, r).triangularView<Eigen::Upper>().transpose().solveInPlace(y);
  const double energy = products[j], rest = energy - y.squaredNorm();
  R_.col(j).head(r) = y;
  ++size_;
  if (!(energy > 0.0 && rest > drop_ * energy)) return;  // dependent: no row of its own
  const double pivot = std::sqrt(rest);
  R_.row(r).head(j).setZero();
  R_(r, j) = pivot;
  RK_.col(r).head(r) = y;
  RK_.row(r).head(r).setZero();
  RK_(r, r) = pivot;
  kept_.push_back(j);
}

void EnergyFactor::appendBlock(const Eigen::MatrixXd& products) {
  const int s = size_, r = rank(), b = static_cast<int>(products.cols());
  if (products.rows() != s + b) throw std::invalid_argument("EnergyFactor::appendBlock: needs size() + b rows");
  // Y = R_K⁻ᵀ M(K, new), then the Schur complement S = M(new, new) − YᵀY = UᵀU of the new block.
  Eigen::MatrixXd Y(r, b);
  for (int i = 0; i < r; ++i) Y.row(i) = products.row(kept_[static_cast<size_t>(i)]);
  RK_.topLeftCorner(r, r).triangularView<Eigen::Upper>().transpose().solveInPlace(Y);
  Eigen::MatrixXd S = products.bottomRows(b).selfadjointView<Eigen::Upper>();
  S.noalias() -= Y.transpose() * Y;
  const Eigen::LLT<Eigen::MatrixXd> llt(S);
  bool independent = llt.info() == Eigen::Success;
  const Eigen::MatrixXd U = llt.matrixU();
  for (int a = 0; independent && a < b; ++a) {
    const double energy = products(s + a, a), rest = U(a, a) * U(a, a);
    independent = energy > 0.0 && rest > drop_ * energy && std::isfinite(rest);
  }
  if (!independent) {  // a dependent column: append's rules, one column at a time
    for (int a = 0; a < b; ++a) append(products.col(a).head(s + a + 1));
    return;
  }
  reserve(R_, s + b);
  reserve(RK_, r + b);
  R_.block(0, s, r, b) = Y;
  R_.block(r, 0, b, s).setZero();
  R_.block(r, s, b, b) = U;
  RK_.block(0, r, r, b) = Y;
  RK_.block(r, 0, b, r).setZero();
  RK_.block(r, r, b, b) = U;
  for (int a = 0; a < b; ++a) kept_.push_back(s + a);
  size_ += b;
}

Eigen::MatrixXd EnergyFactor::whiten(const Eigen::MatrixXd& theta) const {
  return coordinatesOfColumns().leftCols(theta.rows()) * theta;
}

Eigen::MatrixXd EnergyFactor::combination(const Eigen::MatrixXd& U) const {
  const int r = rank();
  const Eigen::MatrixXd CK = RK_.topLeftCorner(r, r).triangularView<Eigen::Upper>().solve(U);
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(size_, U.cols());
  for (int i = 0; i < r; ++i) C.row(kept_[static_cast<size_t>(i)]) = CK.row(i);
  return C;
}

Eigen::MatrixXd EnergyFactor::projections(const Eigen::MatrixXd& products) const {
  if (products.rows() != size_) throw std::invalid_argument("EnergyFactor::projections: needs size() rows");
  const int r = rank();
  Eigen::MatrixXd P(r, products.cols());
  for (int i = 0; i < r; ++i) P.row(i) = products.row(kept_[static_cast<size_t>(i)]);
  RK_.topLeftCorner(r, r).triangularView<Eigen::Upper>().transpose().solveInPlace(P);
  return P;
}

}  // namespace stc::pgd
