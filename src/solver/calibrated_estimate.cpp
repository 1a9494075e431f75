#include "stcontact/solver/calibrated_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>


namespace stc {
namespace {
// Iterates with a larger indicator are kept out of the calibration (see the header).
constexpr double kCalibrationCeiling = 0.1;
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
  for (const Checkpoint& c : checkpoints_) {
    // ‖u_j − u_n‖²_K = Σ δv · δλ (energyProduct of the difference with itself), without temporaries.
    const double squared = (c.s.v - s.v).cwiseProduct(c.s.lambda - s.lambda).sum();
    const double distance = std::sqrt(std::max(0.0, squared));
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
