// The statistics of a scaling study on hand-made measurements with known power laws: series order,
// the reach status, the exponents fitted from the times, the crossover against incremental (inside
// the sizes and extrapolated) and the memory growth per instant.
#include "stcontact/studies/scaling_study.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stc {
namespace {

/// A strategy whose one timed run reaches error 1e-5 (below the 1e-4 target) after `seconds`, or,
/// with reached = false, stops at error 1e-3 with `termination`.
StrategyMeasurement strategy(const std::string& solver, double seconds, bool reached = true,
                             Termination termination = Termination::Converged, double growth_mb = 0.0) {
  StrategyMeasurement m;
  m.solver = solver;
  m.termination = termination;
  m.runs.push_back({1, {{1, 1, 10, 1.0, 1e-1, 0.5 * seconds}, {2, 2, 20, 0.1, reached ? 1e-5 : 1e-3, seconds}}, seconds});
  m.memory = {10.0, 10.0 + growth_mb, true};
  return m;
}

/// The time series m = 100, 400, 1600 with incremental t = 1e-4 m and `solver` t = 1e-2 m^0.5: they
/// cross where m^0.5 = 100, at m = 1e4, beyond the sizes measured.
ScalingStudy timeSeries(const std::string& solver) {
  ScalingStudy study;
  study.solvers = {solver, "incremental"};
  for (int m : {1600, 100, 400}) {  // out of order: the series sorts them
    ScalingPoint p;
    p.mesh_size = 101;
    p.free_dofs = 1000;
    p.in_time_series = true;
    p.comparison.n_dofs = 1142;
    p.comparison.n_contact_nodes = 100;
    p.comparison.n_steps = m;
    // Memory: 1.6 kB per instant more = one interface column of 2 · 100 doubles, per instant.
    const double growth = 1600.0 * m / (1024.0 * 1024.0);
    p.comparison.strategies = {strategy(solver, 1e-2 * std::sqrt(m), true, Termination::Converged, growth),
                               strategy("incremental", 1e-4 * m)};
    study.points.push_back(p);
  }
  return study;
}

TEST(ScalingStudy, SeriesPointsAreSortedBySize) {
  const ScalingStudy study = timeSeries("fas-apriori");
  const auto points = seriesPoints(study, Series::Time);
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[0]->comparison.n_steps, 100);
  EXPECT_EQ(points[2]->comparison.n_steps, 1600);
  EXPECT_TRUE(seriesPoints(study, Series::Mesh).empty());
}

TEST(ScalingStudy, FitsTheExponentOfEachStrategyFromItsTimesToTheTarget) {
  const ScalingStudy study = timeSeries("fas-apriori");
  const SeriesFit a = fitSeries(study, "fas-apriori", Series::Time);
  const SeriesFit b = fitSeries(study, "incremental", Series::Time);
  ASSERT_TRUE(a.fit && b.fit);
  EXPECT_EQ(a.sizes_reached, 3);
  EXPECT_NEAR(a.fit->exponent, 0.5, 1e-12);
  EXPECT_NEAR(b.fit->exponent, 1.0, 1e-12);
}

TEST(ScalingStudy, ExtrapolatesTheCrossingWhenItLiesBeyondTheSizes) {
  const Crossover c = crossoverAgainstIncremental(timeSeries("fas-apriori"), "fas-apriori", Series::Time);
  ASSERT_EQ(c.time_ratio.size(), 3u);
  EXPECT_NEAR(c.time_ratio[0], 1e-2 * 10.0 / (1e-4 * 100.0), 1e-9);  // 10 at m = 100
  EXPECT_FALSE(c.first_faster.has_value());
  ASSERT_TRUE(c.fitted_crossing.has_value());
  EXPECT_NEAR(*c.fitted_crossing, 1e4, 1e-6);
  EXPECT_TRUE(c.faster_beyond);
}

TEST(ScalingStudy, GivesTheFirstSizeWhereTheStrategyIsFaster) {
  ScalingStudy study = timeSeries("fas-apriori");
  for (ScalingPoint& p : study.points)  // ratio 1e-2 √m / (6.25e-4 m) = 16 / √m: 1.6, 0.8, 0.4
    p.comparison.strategies[1] = strategy("incremental", 6.25e-4 * p.comparison.n_steps);
  const Crossover c = crossoverAgainstIncremental(study, "fas-apriori", Series::Time);
  ASSERT_TRUE(c.first_faster.has_value());
  EXPECT_EQ(*c.first_faster, 400.0);
  EXPECT_NEAR(*c.fitted_crossing, 256.0, 1e-6);  // 16 / √m = 1
}

TEST(ScalingStudy, LeavesUnreachedSizesOutOfTheFitAndSaysWhy) {
  ScalingStudy study = timeSeries("latin");
  study.points[0].comparison.strategies[0] = strategy("latin", 1.0, false, Termination::StoppedByCallback);
  const SeriesFit f = fitSeries(study, "latin", Series::Time);
  EXPECT_EQ(f.sizes, 3);
  EXPECT_EQ(f.sizes_reached, 2);
  ASSERT_TRUE(f.fit.has_value());
  EXPECT_NEAR(f.fit->exponent, 0.5, 1e-12);
  EXPECT_EQ(reachStatus(study, study.points[0], "latin"), "time cap");
  EXPECT_EQ(reachStatus(study, study.points[1], "latin"), "reached");
  EXPECT_EQ(reachStatus(study, study.points[1], "latin-pgd"), "not run");
}

TEST(ScalingStudy, MemoryGrowthPerInstantIsCountedInInterfaceColumns) {
  const auto slopes = memorySlopes(timeSeries("fas-apriori"), "fas-apriori");
  ASSERT_EQ(slopes.size(), 2u);
  EXPECT_EQ(slopes[0].m_from, 100);
  EXPECT_EQ(slopes[1].m_to, 1600);
  for (const MemorySlope& s : slopes) {
    EXPECT_NEAR(s.bytes_per_instant, 1600.0, 1e-6);
    EXPECT_NEAR(s.interface_arrays, 1.0, 1e-9);  // 2 n_C = 200 doubles of 8 bytes
    EXPECT_NEAR(s.free_dof_fields, 0.2, 1e-9);   // n_free = 1000 doubles
  }
}

TEST(ScalingStudy, EstimatesMemoryFromTheSizes) {
  ScalingPoint p = timeSeries("latin").points[1];  // m = 100
  p.factor_nonzeros = 131072.0;                    // 1 MB of doubles
  const MemoryEstimate e = estimateMemory(p);
  const double mb = 1024.0 * 1024.0;
  EXPECT_NEAR(e.factor_mb, 1.0, 1e-12);
  EXPECT_NEAR(e.interface_history_mb, 200.0 * 100 * 8 / mb, 1e-12);
  EXPECT_NEAR(e.displacement_history_mb, 1000.0 * 100 * 8 / mb, 1e-12);
  EXPECT_NEAR(e.delassus_mb, 200.0 * 200 * 8 / mb, 1e-12);
  EXPECT_NEAR(e.condensation_mb, 2.0 * 1000 * 200 * 8 / mb, 1e-12);
  EXPECT_NEAR(e.time_matrix_mb, 100.0 * 100 * 8 / mb, 1e-12);
}

}  // namespace
}  // namespace stc
