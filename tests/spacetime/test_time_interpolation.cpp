// Linear interpolation of interface histories in time (src/spacetime/time_interpolation.hpp): exact
// on histories linear between the first grid's instants, the samples themselves kept, and refused
// outside the first grid.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "stcontact/spacetime/time_interpolation.hpp"

namespace {

// h(t) = a + b t + c |t − 0.3| row by row: linear between the instants of any grid that holds 0.3.
Eigen::MatrixXd kinked(const std::vector<double>& times) {
  Eigen::MatrixXd h(3, static_cast<Eigen::Index>(times.size()));
  for (size_t k = 0; k < times.size(); ++k) {
    const double t = times[k];
    h.col(static_cast<Eigen::Index>(k)) << 1.0 + 2.0 * t, -0.5 * t + 3.0 * std::abs(t - 0.3), 4.0 - std::abs(t - 0.3);
  }
  return h;
}

std::vector<double> uniform(int m) {
  std::vector<double> t;
  for (int k = 0; k < m; ++k) t.push_back(static_cast<double>(k) / (m - 1));
  return t;
}

}  // namespace

TEST(TimeInterpolation, ExactOnHistoriesLinearBetweenTheInstants) {
  const std::vector<double> coarse = uniform(11), fine = uniform(101);  // 0.3 on both grids
  const stc::InterfaceHistory h{kinked(coarse), 2.0 * kinked(coarse)};
  const stc::InterfaceHistory out = stc::interpolatedInTime(h, coarse, fine);
  ASSERT_EQ(out.numSteps(), 101);
  EXPECT_LE((out.v - kinked(fine)).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LE((out.lambda - 2.0 * kinked(fine)).cwiseAbs().maxCoeff(), 1e-13);
  // The instants of both grids keep their samples exactly, the last one included.
  for (int k = 0; k < 11; ++k) EXPECT_EQ(out.v.col(10 * k), h.v.col(k));
}

TEST(TimeInterpolation, MidpointsOfAnUnevenGridAreMeans) {
  const std::vector<double> times = {0.0, 0.1, 0.5, 1.0};
  Eigen::MatrixXd v(1, 4);
  v << 0.0, 1.0, -3.0, 7.0;
  const stc::InterfaceHistory out = stc::interpolatedInTime({v, v}, times, {0.05, 0.3, 0.75, 1.0});
  EXPECT_DOUBLE_EQ(out.v(0, 0), 0.5);
  EXPECT_DOUBLE_EQ(out.v(0, 1), -1.0);
  EXPECT_DOUBLE_EQ(out.v(0, 2), 2.0);
  EXPECT_DOUBLE_EQ(out.lambda(0, 3), 7.0);
}

TEST(TimeInterpolation, RefusesGridsThatDoNotFit) {
  const std::vector<double> times = {0.0, 0.5, 1.0};
  const stc::InterfaceHistory h{Eigen::MatrixXd::Ones(2, 3), Eigen::MatrixXd::Ones(2, 3)};
  EXPECT_THROW(stc::interpolatedInTime(h, {0.0, 1.0}, {0.5}), std::invalid_argument);       // 3 columns, 2 instants
  EXPECT_THROW(stc::interpolatedInTime(h, {0.0, 0.5, 0.5}, {0.5}), std::invalid_argument);  // not increasing
  EXPECT_THROW(stc::interpolatedInTime(h, times, {1.5}), std::invalid_argument);            // outside
  EXPECT_THROW(stc::interpolatedInTime(h, times, {-0.1}), std::invalid_argument);
  EXPECT_EQ(stc::interpolatedInTime(h, times, {}).numSteps(), 0);
}
