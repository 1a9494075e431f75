// The growth-exponent fit of the scaling study on data with a known exponent, a known scatter (so a
// known standard error) and a known crossing.
#include "stcontact/studies/growth_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace stc {
namespace {

TEST(PowerLawFit, RecoversTheExponentAndPrefactorOfAnExactPowerLaw) {
  std::vector<double> sizes = {201, 801, 2001, 5003}, values;
  for (double s : sizes) values.push_back(3.0 * std::pow(s, 1.5));
  const PowerLawFit fit = fitPowerLaw(sizes, values);
  EXPECT_EQ(fit.points, 4);
  EXPECT_NEAR(fit.exponent, 1.5, 1e-12);
  EXPECT_NEAR(std::exp(fit.log_prefactor), 3.0, 1e-9);
  EXPECT_NEAR(fit.exponent_stderr, 0.0, 1e-9);
  EXPECT_NEAR(fit.at(1000.0), 3.0 * std::pow(1000.0, 1.5), 1e-6 * std::pow(1000.0, 1.5));
}

// log s = 0, 1, 2 and log t = 1 + 2 log s + (d, −2d, d): the residuals are orthogonal to 1 and log s,
// so the slope stays 2; sumsq = 6d², s² = sumsq/(n − 2) = 6d², Σ(x − x̄)² = 2, so the standard error
// of the slope is sqrt(s²/2) = √3 d (ordinary least squares, e.g. GSL manual "Linear regression").
TEST(PowerLawFit, StandardErrorOfTheExponentFollowsTheScatter) {
  const double d = 0.05;
  const std::vector<double> sizes = {1.0, std::exp(1.0), std::exp(2.0)};
  const std::vector<double> values = {std::exp(1.0 + d), std::exp(3.0 - 2.0 * d), std::exp(5.0 + d)};
  const PowerLawFit fit = fitPowerLaw(sizes, values);
  EXPECT_NEAR(fit.exponent, 2.0, 1e-12);
  EXPECT_NEAR(fit.log_prefactor, 1.0, 1e-12);
  EXPECT_NEAR(fit.residual_sumsq, 6.0 * d * d, 1e-12);
  EXPECT_NEAR(fit.exponent_stderr, std::sqrt(3.0) * d, 1e-12);
}

TEST(PowerLawFit, TwoPointsGiveTheExponentButNoStandardError) {
  const PowerLawFit fit = fitPowerLaw({10.0, 100.0}, {1.0, 100.0});
  EXPECT_NEAR(fit.exponent, 2.0, 1e-12);
  EXPECT_TRUE(std::isnan(fit.exponent_stderr));
}

TEST(PowerLawFit, RefusesTooFewPointsNonPositiveValuesAndOneSize) {
  EXPECT_THROW(fitPowerLaw({10.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW(fitPowerLaw({10.0, 20.0}, {1.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(fitPowerLaw({10.0, 10.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(fitPowerLaw({10.0, 20.0}, {1.0}), std::invalid_argument);
}

// t_a = 2 s and t_b = s²/2 are equal at s = 4.
TEST(CrossingSize, IsWhereTwoFittedLawsAreEqual) {
  const PowerLawFit a = fitPowerLaw({1.0, 10.0}, {2.0, 20.0});
  const PowerLawFit b = fitPowerLaw({1.0, 10.0}, {0.5, 50.0});
  const auto s = crossingSize(a, b);
  ASSERT_TRUE(s.has_value());
  EXPECT_NEAR(*s, 4.0, 1e-9);
  EXPECT_NEAR(a.at(*s), b.at(*s), 1e-9);
}

TEST(CrossingSize, IsEmptyForParallelLaws) {
  PowerLawFit a, b;
  a.exponent = b.exponent = 1.0;
  a.log_prefactor = std::log(2.0);
  b.log_prefactor = std::log(3.0);
  EXPECT_FALSE(crossingSize(a, b).has_value());
}

}  // namespace
}  // namespace stc
