#include "stcontact/solver/calibrated_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "stcontact/core/threads.hpp"

namespace stc {
namespace {
// Iterates with a larger indicator are kept out of the calibration (see the header).
constexpr double kCalibrationCeiling = 0.1;

// ‖u_j − u_n‖²_K = Σ δv · δλ over the rows and instants (energyProduct of the difference with itself)
// for every checkpoint j, in one pass over s_n: each instant's column of s_n is read once for all
// checkpoints, the instants split over threads, and the columns' sums added in order (the same
// arithmetic on any number of threads).
template <class Checkpoints>
Eigen::VectorXd squaredDistances(const Checkpoints& checkpoints, const InterfaceHistory& s) {
  const auto count = static_cast<Eigen::Index>(checkpoints.size());
  const auto m = static_cast<int>(s.v.cols());
  Eigen::MatrixXd per_instant(count, m);
  parallelRanges(m, threadsForField(s.v.size()), [&](int begin, int end) {
    for (int k = begin; k < end; ++k)
      for (Eigen::Index j = 0; j < count; ++j) {
        const InterfaceHistory& c = checkpoints[static_cast<std::size_t>(j)].s;
        per_instant(j, k) = (c.v.col(k) - s.v.col(k)).dot(c.lambda.col(k) - s.lambda.col(k));
      }
  });
  return per_instant.rowwise().sum();
}
}  // namespace

CalibratedIndicatorEstimator::CalibratedIndicatorEstimator(double safety, int count, double spacing)
    : safety_(safety), spacing_(spacing), count_(count) {
  if (!(safety >= 1.0) || count < 1 || !(spacing > 1.0))
    throw std::invalid_argument("CalibratedIndicatorEstimator: needs safety >= 1, count >= 1, spacing > 1");
}

double CalibratedIndicatorEstimator::record(const InterfaceHistory& s, double indicator, double energy) {
  double bound = -1.0;
  double calibrating = 0.0;  // the largest d_jn / η_j of the checkpoints that calibrate
  double recent = 0.0;       // the largest d_kn / η_k of those too recent to calibrate
  const Eigen::VectorXd squared = squaredDistances(checkpoints_, s);
  for (std::size_t j = 0; j < checkpoints_.size(); ++j) {
    const Checkpoint& c = checkpoints_[j];
    const double distance = std::sqrt(std::max(0.0, squared[static_cast<Eigen::Index>(j)]));
    if (!(c.indicator >= 2.0 * safety_ * indicator)) {
      recent = std::max(recent, distance / c.indicator);
      continue;
    }
    calibrating = std::max(calibrating, distance / c.indicator);
    bound = std::max(bound, safety_ * indicator * distance / (c.indicator - safety_ * indicator));
  }
  if (bound > 0.0 && recent > calibrating) bound *= recent / calibrating;  // growth already seen (header)
  if (indicator < kCalibrationCeiling && (checkpoints_.empty() || indicator * spacing_ <= checkpoints_.back().indicator)) {
    checkpoints_.push_back({s, indicator});
    if (static_cast<int>(checkpoints_.size()) > count_) checkpoints_.pop_front();
  }
  if (bound < 0.0 || !(energy > 0.0)) return std::numeric_limits<double>::infinity();
  return bound / std::sqrt(energy);
}

}  // namespace stc
