// Termination statuses of the shared iteration bookkeeping.
#include <gtest/gtest.h>

#include <limits>

#include "stcontact/solver/iteration_monitor.hpp"

namespace {
stc::InterfaceHistory zeros() { return stc::InterfaceHistory::zerosWithRows(2, 2); }
}  // namespace

// Without an energy the monitor has no error estimate: the indicator stands in for it, so these
// cases test the bookkeeping alone (the estimate: tests/solver/test_error_estimate.cpp).

TEST(IterationMonitor, NaNIsANumericalIssue) {
  stc::IterationMonitor monitor("test", {{1e-6, 100, 0}}, nullptr);
  EXPECT_FALSE(monitor.record(1, 0.5, zeros(), 0, 0));
  EXPECT_TRUE(monitor.record(2, std::numeric_limits<double>::quiet_NaN(), zeros(), 0, 0));
  EXPECT_EQ(monitor.finish().termination, stc::Termination::NumericalIssue);
}

TEST(IterationMonitor, NoProgressIsStagnation) {
  stc::IterationMonitor monitor("test", {{1e-6, 1000, 10}}, nullptr);
  int iterations = 0;
  while (!monitor.record(++iterations, 0.1, zeros(), 0, 0)) ASSERT_LT(iterations, 100);
  const auto summary = monitor.finish();
  EXPECT_EQ(summary.termination, stc::Termination::Stagnated);
  EXPECT_EQ(summary.iterations, 11);  // best at 1, ten more without a 1% decrease
}

TEST(IterationMonitor, ToleranceConverges) {
  stc::IterationMonitor monitor("test", {{1e-3, 100, 0}}, nullptr);
  EXPECT_FALSE(monitor.record(1, 1e-2, zeros(), 0, 0));
  EXPECT_TRUE(monitor.record(2, 1e-4, zeros(), 0, 0));
  const auto summary = monitor.finish();
  EXPECT_TRUE(summary.converged());
  EXPECT_EQ(summary.relaxations, 2);
  EXPECT_EQ(summary.indicator, 1e-4);
}
