#include "stcontact/solver/error_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "stcontact/linalg/dense_decompositions.hpp"

namespace stc {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A difference below this share of the iterate's energy norm is round-off: ε times the growth of
// rounding errors through the stages' factorisations. `fas-aposteriori` with the exact solution's
// SVD modes on 801 contact nodes reaches true error 2.5e-14, where its differences no longer shrink
// and no extrapolation applies; without this rule it ran to the stagnation limit (1002 relaxations).
constexpr double kRoundOff = 1e-12;

// Solves the symmetric system M c = b in the least-squares sense, ignoring directions of M below
// 1e-12 of its largest eigenvalue (nearly parallel differences: a lower order is all they hold).
Eigen::VectorXd pseudoSolve(const Eigen::MatrixXd& M, const Eigen::VectorXd& b) {
  const linalg::SymmetricEigen eig = linalg::symmetricEigen(M);
  const Eigen::VectorXd& d = eig.values;
  const double cutoff = 1e-12 * d.cwiseAbs().maxCoeff();
  Eigen::VectorXd coordinates = eig.vectors.transpose() * b;
  for (Eigen::Index i = 0; i < d.size(); ++i) coordinates[i] = d[i] > cutoff ? coordinates[i] / d[i] : 0.0;
  return eig.vectors * coordinates;
}

}  // namespace

double energyProduct(const InterfaceHistory& d1, const InterfaceHistory& d2) {
  // Symmetric in exact arithmetic; the mean of both orders keeps round-off symmetric too.
  return 0.5 * (d1.v.cwiseProduct(d2.lambda).sum() + d2.v.cwiseProduct(d1.lambda).sum());
}

double energyOfDifference(const InterfaceHistory& a, const InterfaceHistory& b) {
  return ((a.v - b.v).array() * (a.lambda - b.lambda).array()).sum();
}

ErrorEstimator::ErrorEstimator(int period, int order, double safety, int window, double min_rate)
    : period_(std::max(1, period)),
      order_(std::max(1, order)),
      safety_(std::max(1.0, safety)),
      window_(std::max(1, window)),
      smallest_share_(std::max(0.0, min_rate) / (1.0 + std::max(0.0, min_rate))),
      sequences_(period_) {}

void ErrorEstimator::reset() { sequences_.assign(period_, Sequence{}); }

double ErrorEstimator::extrapolatedError(const Eigen::MatrixXd& gram) const {
  const Eigen::Index K = order_;
  // c = argmin ‖w_K + Σ_{j<K} c_j w_j‖: normal equations G_{<K} c = −⟨w_j, w_K⟩.
  Eigen::VectorXd c(K + 1);
  c.head(K) = pseudoSolve(gram.topLeftCorner(K, K), -gram.col(K).head(K));
  c[K] = 1.0;
  const double sum = c.sum();  // Σc = P(1): zero when the iteration does not contract
  if (!(std::abs(sum) > 1e-12 * c.cwiseAbs().sum())) return kInfinity;
  Eigen::VectorXd beta(K + 1);
  double partial = 0.0;
  for (Eigen::Index i = 0; i <= K; ++i) beta[i] = (partial += c[i] / sum);
  return std::sqrt(std::max(0.0, beta.dot(gram * beta)));
}

double ErrorEstimator::extend(Sequence& q, const InterfaceHistory& s, double energy,
                              std::optional<double> unrelaxed, double stage_error) const {
  double estimate = kInfinity;
  if (q.last) {
    q.differences.push_back({s.v - q.last->v, s.lambda - q.last->lambda});
    const bool full = static_cast<Eigen::Index>(q.differences.size()) > order_ + 1;
    if (full) q.differences.pop_front();
    const Eigen::Index n = static_cast<Eigen::Index>(q.differences.size());
    Eigen::MatrixXd gram(n, n);
    gram.topLeftCorner(n - 1, n - 1) = full ? q.gram.bottomRightCorner(n - 1, n - 1) : q.gram;
    for (Eigen::Index i = 0; i < n; ++i) gram(i, n - 1) = gram(n - 1, i) = energyProduct(q.differences[i], q.differences.back());
    q.gram = std::move(gram);
    const InterfaceHistory& w = q.differences.back();
    // The map's own step: the difference itself, or the relaxed step's unrelaxed one.
    const bool stands_still = unrelaxed ? *unrelaxed == 0.0 : w.v.isZero(0.0) && w.lambda.isZero(0.0);
    // The energy of a difference of two iterates in equilibrium is Σ δv·δλ ≥ 0; a negative one (beyond
    // round-off) says the iterates are not both in equilibrium, and the products mean nothing.
    const double squared = q.gram(n - 1, n - 1);
    const double scale = std::sqrt(w.v.squaredNorm() * w.lambda.squaredNorm());
    const bool not_an_energy = squared < -kRoundOff * scale;
    const double size = std::sqrt(std::max(0.0, squared));
    const double step = unrelaxed.value_or(size);
    // A difference larger than every earlier one of the sequence: no contraction (yet).
    const bool growing = n > 1 && q.gram.diagonal().head(n - 1).maxCoeff() <= q.gram(n - 1, n - 1);
    if (stands_still) {
      estimate = 0.0;  // the iteration stands still: a fixed point
    } else if (not_an_energy || size == 0.0) {
      estimate = kInfinity;  // no energy to extrapolate from: the estimate cannot tell
    } else if (energy > 0.0 && step <= kRoundOff * std::sqrt(energy)) {
      estimate = step / std::sqrt(energy);  // a fixed point to round-off: the error is not resolved below it
    } else if (n == order_ + 1 && !growing && energy > 0.0) {
      q.factors.push_back(std::max(extrapolatedError(q.gram) / size, smallest_share_));
      if (static_cast<int>(q.factors.size()) > window_) q.factors.pop_front();
      const double factor = *std::max_element(q.factors.begin(), q.factors.end());
      if (std::isfinite(factor)) estimate = safety_ * (factor * size + stage_error) / std::sqrt(energy);
    }
  }
  q.last = s;
  return estimate;
}

double ErrorEstimator::record(const InterfaceHistory& s, double energy, std::optional<double> unrelaxed_step,
                              double stage_error) {
  return extend(sequences_[count_++ % period_], s, energy, unrelaxed_step, stage_error);
}

}  // namespace stc
