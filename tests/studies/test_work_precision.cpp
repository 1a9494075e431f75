// The statistics of a work-precision comparison on hand-made histories: the median, the first point
// reaching a target error, the median over repeats of the work to reach it, the repeat drawn, and the
// copy of the measured errors onto timed runs of the same solver.
#include "stcontact/studies/work_precision.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "stcontact/studies/comparison.hpp"

namespace stc {
namespace {

/// A history whose error divides by 10 every iteration (iteration i: error 0.5·10^-i, so 10^-i is
/// first reached at iteration i), with `seconds_per_iteration` of work, 2 relaxations and 100 sparse
/// solves per iteration.
std::vector<WorkPoint> geometricHistory(int iterations, double seconds_per_iteration) {
  std::vector<WorkPoint> points;
  for (int i = 1; i <= iterations; ++i) {
    const double error = 0.5 * std::pow(10.0, -i);
    points.push_back({i, 2 * i, 100L * i, 2.0 * error, error, seconds_per_iteration * i});
  }
  return points;
}

TEST(Median, OfAnOddCountIsTheMiddleValue) { EXPECT_DOUBLE_EQ(median({5.0, 1.0, 3.0}), 3.0); }

TEST(Median, OfAnEvenCountIsTheMeanOfTheTwoMiddleValues) {
  EXPECT_DOUBLE_EQ(median({4.0, 1.0, 10.0, 2.0}), 3.0);
}

TEST(Median, IsNotMovedByOneOutlier) { EXPECT_DOUBLE_EQ(median({1.0, 1.1, 1000.0}), 1.1); }

TEST(Median, OfNothingThrows) { EXPECT_THROW(median({}), std::invalid_argument); }

TEST(FirstReaching, ReturnsTheFirstPointAtOrBelowTheTarget) {
  const auto points = geometricHistory(8, 0.5);
  const auto p = firstReaching(points, 1e-4);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->iteration, 4);
  EXPECT_EQ(p->relaxations, 8);
  EXPECT_EQ(p->sparse_solves, 400);
  EXPECT_DOUBLE_EQ(p->wall_s, 2.0);
}

TEST(FirstReaching, IgnoresALaterRiseAndPointsWithoutError) {
  std::vector<WorkPoint> points = {{1, 1, 10, 1.0, std::nullopt, 0.1},  // error unknown: skipped
                                   {2, 2, 20, 0.1, 5e-3, 0.2},
                                   {3, 3, 30, 0.1, 2e-2, 0.3},  // rises again: the first crossing counts
                                   {4, 4, 40, 0.1, 1e-3, 0.4}};
  const auto p = firstReaching(points, 1e-2);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->iteration, 2);
}

TEST(FirstReaching, IsEmptyWhenTheTargetIsNeverReached) {
  EXPECT_FALSE(firstReaching(geometricHistory(3, 1.0), 1e-6).has_value());
}

TEST(ReachOf, TakesTheMedianOverRepeatsOfTheTimeToReach) {
  // Three repeats of the same iterations at different speeds: 1e-4 at iteration 4.
  const std::vector<TimedRun> runs = {{1, geometricHistory(6, 1.0), 6.0},
                                      {2, geometricHistory(6, 3.0), 18.0},
                                      {3, geometricHistory(6, 2.0), 12.0}};
  const Reach r = reachOf(runs, 1e-4);
  EXPECT_EQ(r.repeats_reached, 3);
  ASSERT_TRUE(r.wall_s.has_value());
  EXPECT_DOUBLE_EQ(*r.wall_s, 8.0);  // 4 iterations × the median 2 s
  EXPECT_DOUBLE_EQ(*r.relaxations, 8.0);
  EXPECT_DOUBLE_EQ(*r.sparse_solves, 400.0);
}

TEST(ReachOf, CountsOnlyTheRepeatsThatReachedTheTarget) {
  const std::vector<TimedRun> runs = {{1, geometricHistory(6, 1.0), 6.0}, {2, geometricHistory(3, 1.0), 3.0}};
  const Reach r = reachOf(runs, 1e-5);
  EXPECT_EQ(r.repeats_reached, 1);
  EXPECT_DOUBLE_EQ(*r.wall_s, 5.0);
  const Reach never = reachOf(runs, 1e-9);
  EXPECT_EQ(never.repeats_reached, 0);
  EXPECT_FALSE(never.wall_s.has_value());
  EXPECT_FALSE(never.relaxations.has_value());
}

TEST(MedianRepeat, IsTheRepeatWithTheMedianTotalTime) {
  const std::vector<TimedRun> runs = {{1, {}, 9.0}, {2, {}, 4.0}, {3, {}, 5.0}};
  EXPECT_EQ(medianRepeat(runs), 3);
  const std::vector<TimedRun> two = {{1, {}, 9.0}, {2, {}, 4.0}};
  EXPECT_EQ(medianRepeat(two), 2);  // the lower middle
  EXPECT_THROW(medianRepeat({}), std::invalid_argument);
}

TEST(CopyErrors, GivesTimedRunsTheErrorsOfTheMeasuredRun) {
  const auto measured = geometricHistory(5, 1.0);
  auto timed = geometricHistory(5, 2.0);
  for (auto& p : timed) p.error.reset();
  EXPECT_TRUE(copyErrors(measured, timed));
  for (std::size_t i = 0; i < timed.size(); ++i) {
    ASSERT_TRUE(timed[i].error.has_value());
    EXPECT_DOUBLE_EQ(*timed[i].error, *measured[i].error);
    EXPECT_DOUBLE_EQ(timed[i].wall_s, 2.0 * (i + 1));  // the timing stays the timed run's
  }
}

TEST(CopyErrors, RefusesPointsWhoseIndicatorDiffers) {
  const auto measured = geometricHistory(4, 1.0);
  auto timed = geometricHistory(4, 1.0);
  timed[2].indicator *= 1.01;
  EXPECT_FALSE(copyErrors(measured, timed));
  EXPECT_TRUE(timed[1].error.has_value());
  EXPECT_FALSE(timed[2].error.has_value());
}

TEST(CopyErrors, ReportsADifferentIterationCount) {
  const auto measured = geometricHistory(3, 1.0);
  auto timed = geometricHistory(5, 1.0);
  EXPECT_FALSE(copyErrors(measured, timed));
  EXPECT_TRUE(timed[2].error.has_value());
  EXPECT_FALSE(timed[3].error.has_value());
}

TEST(Summarize, ReportsEachTargetAndTheTimeRatio) {
  StrategyMeasurement fast, slow;
  fast.solver = "fast";
  slow.solver = "slow";
  for (int r = 1; r <= 3; ++r) {
    fast.runs.push_back({r, geometricHistory(7, 1.0 * r), 7.0 * r});
    slow.runs.push_back({r, geometricHistory(7, 4.0 * r), 28.0 * r});
  }
  const StrategySummary f = summarize(fast), s = summarize(slow);
  ASSERT_EQ(f.reaches.size(), targetErrors().size());
  EXPECT_DOUBLE_EQ(f.median_total_s, 14.0);
  EXPECT_EQ(f.median_repeat, 2);
  for (std::size_t t = 0; t < targetErrors().size(); ++t) {
    ASSERT_TRUE(timeRatio(f, s, t).has_value());
    EXPECT_DOUBLE_EQ(*timeRatio(f, s, t), 0.25);
  }
  EXPECT_DOUBLE_EQ(*f.reaches[1].wall_s, 8.0);  // 1e-4 at iteration 4, median 2 s per iteration
}

}  // namespace
}  // namespace stc
