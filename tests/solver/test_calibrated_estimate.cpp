// The calibrated indicator estimate of FAS (src/solver/calibrated_estimate.hpp) on synthetic
// sequences s_n = s* + ε_n d whose true error ε_n ‖d‖_K is known: it bounds the error from above
// while the ratio of error to indicator grows by at most the safety factor s, and by at most
// 2 s times the error when that ratio is constant.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "stcontact/core/threads.hpp"
#include "stcontact/solver/calibrated_estimate.hpp"
#include "stcontact/solver/error_estimate.hpp"

namespace {

// A limit s* and a direction d with ‖d‖²_K = Σ δv·δλ = 3 (λ = 3 v on one row, one instant).
struct Sequence {
  stc::InterfaceHistory limit{Eigen::MatrixXd::Constant(2, 3, 0.5), Eigen::MatrixXd::Constant(2, 3, -1.0)};
  stc::InterfaceHistory direction{Eigen::MatrixXd::Zero(2, 3), Eigen::MatrixXd::Zero(2, 3)};
  Sequence() {
    direction.v(0, 0) = 1.0;
    direction.lambda(0, 0) = 3.0;
  }
  stc::InterfaceHistory at(double error) const {
    return {limit.v + error * direction.v, limit.lambda + error * direction.lambda};
  }
  double norm() const { return std::sqrt(stc::energyProduct(direction, direction)); }
};

}  // namespace

TEST(CalibratedIndicatorEstimator, BoundsTheErrorWithinTwiceTheSafetyWhenTheRatioIsConstant) {
  const Sequence q;
  const double safety = 2.5, ratio = 7.0;  // error = ratio · indicator, throughout
  stc::CalibratedIndicatorEstimator estimator(safety);
  int finite = 0;
  for (int n = 1; n <= 30; ++n) {
    const double error = std::pow(0.6, n), indicator = error / ratio;
    const double estimate = estimator.record(q.at(error), indicator, 1.0);
    if (!std::isfinite(estimate)) continue;
    ++finite;
    EXPECT_GE(estimate, error * q.norm() * (1 - 1e-12)) << n;
    EXPECT_LE(estimate, 2 * safety * error * q.norm()) << n;
  }
  EXPECT_GE(finite, 20);
}

TEST(CalibratedIndicatorEstimator, StillBoundsTheErrorWhenTheRatioGrowsWithinTheSafety) {
  // The ratio error/indicator doubles along the run (s = 2.5 covers it): the bound holds.
  const Sequence q;
  stc::CalibratedIndicatorEstimator estimator(2.5);
  int finite = 0;
  for (int n = 1; n <= 30; ++n) {
    const double error = std::pow(0.5, n), ratio = 4.0 * (1.0 + n / 30.0);
    const double estimate = estimator.record(q.at(error), error / ratio, 1.0);
    if (!std::isfinite(estimate)) continue;
    ++finite;
    EXPECT_GE(estimate, error * q.norm()) << n;
  }
  EXPECT_GE(finite, 20);
}

TEST(CalibratedIndicatorEstimator, IsInfiniteUntilAnEarlierIndicatorIsTwiceTheSafetyLarger) {
  const Sequence q;
  stc::CalibratedIndicatorEstimator estimator(2.0);  // needs a checkpoint with η_j ≥ 4 η_n
  EXPECT_TRUE(std::isinf(estimator.record(q.at(1.0), 2.0, 1.0)));     // η ≥ 0.1: never a checkpoint
  EXPECT_TRUE(std::isinf(estimator.record(q.at(0.5), 0.5, 1.0)));     // nor this one (pre-asymptotic)
  EXPECT_TRUE(std::isinf(estimator.record(q.at(0.02), 0.02, 1.0)));   // 0.5 ≥ 4 · 0.02, but no checkpoint: the first
  EXPECT_TRUE(std::isinf(estimator.record(q.at(0.01), 0.01, 1.0)));   // 0.02 < 4 · 0.01
  EXPECT_TRUE(std::isfinite(estimator.record(q.at(0.005), 0.005, 1.0)));  // 0.02 ≥ 4 · 0.005
  // The relative error: the bound over √E.
  stc::CalibratedIndicatorEstimator other(2.0);
  other.record(q.at(0.05), 0.05, 1.0);
  const double absolute = other.record(q.at(0.01), 0.01, 1.0);
  stc::CalibratedIndicatorEstimator scaled(2.0);
  scaled.record(q.at(0.05), 0.05, 4.0);
  EXPECT_DOUBLE_EQ(scaled.record(q.at(0.01), 0.01, 4.0), absolute / 2.0);
  EXPECT_THROW(stc::CalibratedIndicatorEstimator(0.5), std::invalid_argument);
}

namespace {

// An iterate at (a, b) along two K-orthogonal directions, each of ‖·‖²_K = 3: distances are √3 |Δ(a, b)|.
stc::InterfaceHistory pointAt(double a, double b) {
  stc::InterfaceHistory s{Eigen::MatrixXd::Zero(2, 3), Eigen::MatrixXd::Zero(2, 3)};
  s.v(0, 0) = a;
  s.lambda(0, 0) = 3.0 * a;
  s.v(1, 1) = b;
  s.lambda(1, 1) = 3.0 * b;
  return s;
}

// Checkpoints A (η = 1e-2, calibrates the iterate at η_n = 1e-3 for s = 2.5) and B (η = 4e-3 < 2 s η_n:
// too recent) at (0.1, 0) and (0, b), then the iterate at the origin; returns its estimate.
double estimateWithRecentCheckpointAt(double b) {
  stc::CalibratedIndicatorEstimator estimator(2.5);
  estimator.record(pointAt(0.1, 0.0), 1e-2, 1.0);
  estimator.record(pointAt(0.0, b), 4e-3, 1.0);
  return estimator.record(pointAt(0.0, 0.0), 1e-3, 1.0);
}

}  // namespace

TEST(CalibratedIndicatorEstimator, ScalesTheBoundByTheGrowthARecentCheckpointShows) {
  const double root3 = std::sqrt(3.0);
  const double calibrated = 2.5 * 1e-3 * 0.1 * root3 / (1e-2 - 2.5 * 1e-3);  // s η_n d_An / (η_A − s η_n)
  const double ratio_a = 0.1 * root3 / 1e-2;
  // B's ratio d_Bn/η_B = 0.05 √3 / 4e-3 is 1.25 times A's: the ratio has grown since A.
  EXPECT_NEAR(estimateWithRecentCheckpointAt(0.05), calibrated * (0.05 * root3 / 4e-3) / ratio_a, 1e-15);
  // B's ratio 0.02 √3 / 4e-3 is half A's: nothing seen, the calibrated bound alone.
  EXPECT_NEAR(estimateWithRecentCheckpointAt(0.02), calibrated, 1e-15);
}

// The distances to the checkpoints are taken by instants on the threads from 2^16 entries per field
// (docs/threads.md): the estimates of a long random sequence are bitwise those of one thread.
TEST(CalibratedIndicatorEstimator, SplittingTheInstantsOverThreadsChangesNoBit) {
  const Eigen::Index rows = 60, m = 2001;  // 120 060 entries per field
  const stc::InterfaceHistory limit{Eigen::MatrixXd::Random(rows, m), Eigen::MatrixXd::Random(rows, m)};
  const stc::InterfaceHistory direction{Eigen::MatrixXd::Random(rows, m), Eigen::MatrixXd::Random(rows, m)};
  const auto estimates = [&](int threads) {
    const stc::ThreadCountScope scope(threads);
    stc::CalibratedIndicatorEstimator estimator;
    std::vector<double> out;
    for (int n = 1; n <= 12; ++n) {
      const double error = std::pow(0.5, n);
      out.push_back(estimator.record({limit.v + error * direction.v, limit.lambda + error * direction.lambda},
                                     error / 5.0, 1.0));
    }
    return out;
  };
  const std::vector<double> one = estimates(1), two = estimates(2);
  ASSERT_TRUE(std::isfinite(one.back())) << "the sequence must reach calibrated estimates";
  for (std::size_t n = 0; n < one.size(); ++n) EXPECT_EQ(std::memcmp(&one[n], &two[n], sizeof(double)), 0) << n;
}
