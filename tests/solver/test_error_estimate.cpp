// The error estimate of src/solver/error_estimate.hpp on sequences whose error is known exactly, and
// the energy of src/solver/equilibrium_energy.hpp against the energy of the rebuilt full field.
#include <gtest/gtest.h>

#include <cmath>

#include "fixtures/seed_scene.hpp"
#include "stcontact/incremental/condensed_interface.hpp"
#include "stcontact/incremental/error_reference.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/latin/global_stage.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/operators/displacement.hpp"
#include "stcontact/solver/equilibrium_energy.hpp"
#include "stcontact/solver/error_estimate.hpp"

namespace {

// An "equilibrated" iterate whose energy products are Euclidean ones: v = λ = x (Σ δv·δλ = ‖δx‖²).
stc::InterfaceHistory iterate(const Eigen::VectorXd& x) {
  Eigen::MatrixXd m = x;
  return {m, m};
}

// x_n = x* + e_n with e_n = ρ^t (cos tθ a + sin tθ b), t = n / period, a ⊥ b unit vectors: a
// dominant eigenvalue ρ e^{iθ} per period. Returns estimate / true error at the last of `count`
// records (E = 1).
double estimateOverError(double rho, double theta, int count, int period = 1) {
  Eigen::VectorXd a = Eigen::VectorXd::Zero(4), b = Eigen::VectorXd::Zero(4), star(4);
  a[0] = 1.0;
  b[1] = 1.0;
  star << 0.3, -0.2, 0.7, 1.1;
  stc::ErrorEstimator estimator(period);
  double ratio = NAN;
  for (int n = 0; n < count; ++n) {
    const double t = static_cast<double>(n) / period;  // the eigenvalue acts once per period
    const Eigen::VectorXd e = std::pow(rho, t) * (std::cos(t * theta) * a + std::sin(t * theta) * b);
    const double estimate = estimator.record(iterate(star + e), 1.0);
    ratio = estimate / e.norm();
  }
  return ratio;
}

}  // namespace

// The extrapolation is exact for these sequences (one real or complex mode), so the estimate is the
// safety factor (2) times the true error, whatever the sign or rotation of the eigenvalue.
TEST(ErrorEstimator, IsTwiceTheErrorOfAMonotoneContraction) {
  EXPECT_NEAR(estimateOverError(0.9, 0.0, 30), 2.0, 1e-9);
}

TEST(ErrorEstimator, IsTwiceTheErrorOfAnAlternatingContraction) {
  EXPECT_NEAR(estimateOverError(0.9, M_PI, 30), 2.0, 1e-9);
}

TEST(ErrorEstimator, IsTwiceTheErrorOfARotatingContraction) {
  EXPECT_NEAR(estimateOverError(0.7, 2.0, 30), 2.0, 1e-9);
}

TEST(ErrorEstimator, ComparesIteratesOnePeriodApart) {
  EXPECT_NEAR(estimateOverError(0.5, 0.4, 30, 2), 2.0, 1e-9);
}

TEST(ErrorEstimator, IsInfiniteUntilThreeDifferencesAreKnownAndWhileTheyGrow) {
  stc::ErrorEstimator estimator;  // period 1, order 2: the first estimate at the 4th record
  Eigen::VectorXd x(2);
  x << 1.0, 2.0;
  for (double scale : {1.0, 2.0, 4.0, 8.0, 16.0})  // differences x, 2x, 4x, 8x: diverging
    EXPECT_TRUE(std::isinf(estimator.record(iterate(scale * x), 1.0))) << scale;
  EXPECT_EQ(estimator.record(iterate(16 * x), 1.0), 0.0);  // standing still
}

// Iterates that jitter at round-off about their fixed point (differences 1e-15 of their size, growing
// and shrinking at random) stop the solve: the differences are what the estimate reports, not +∞.
TEST(ErrorEstimator, IsTheDifferenceOnceTheIterationStandsStillToRoundOff) {
  stc::ErrorEstimator estimator;
  Eigen::VectorXd star(3);
  star << 0.3, -0.2, 0.7;
  const double jitter[] = {1e-15, -3e-15, 2e-15, -4e-15, 5e-16, 6e-15};
  double estimate = NAN;
  for (double j : jitter) estimate = estimator.record(iterate(star + Eigen::VectorXd::Constant(3, j)), star.squaredNorm());
  EXPECT_TRUE(std::isfinite(estimate));
  EXPECT_LE(estimate, 1e-12);
  EXPECT_GT(estimate, 0.0);
}

TEST(ErrorEstimator, ExtrapolatesAMixtureOfAMonotoneAndAnAlternatingMode) {
  // e_n = 0.9ⁿ a + (−0.8)ⁿ b: the one-mode model misjudges it (it blends the two), the extrapolation
  // of order 2 does not.
  Eigen::VectorXd a = Eigen::VectorXd::Zero(3), b = Eigen::VectorXd::Zero(3), star(3);
  a[0] = 1.0;
  b[1] = 3.0;
  star << 0.5, 0.25, -1.0;
  stc::ErrorEstimator estimator;
  double ratio = NAN;
  for (int n = 0; n < 12; ++n) {
    const Eigen::VectorXd e = std::pow(0.9, n) * a + std::pow(-0.8, n) * b;
    ratio = estimator.record(iterate(star + e), 1.0) / e.norm();
  }
  EXPECT_NEAR(ratio, 2.0, 1e-6);
}

// E of docs/method.md §2 for equilibrated iterates, from the interface alone, against the energy of
// the full displacement rebuilt with K_ff⁻¹: the incremental solution, and a LATIN iterate.
TEST(EquilibriumEnergy, EqualsTheEnergyOfTheRebuiltFullField) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(31, 41));
  const stc::CholmodFactor K(problem.stiffness_free, "K");
  stc::latin::GlobalStage global(problem);
  const stc::EquilibriumEnergy energy(problem, global.factor());
  const stc::SolveResult reference = stc::solveIncremental(problem);
  stc::InterfaceHistory hat, s;
  stc::latin::localStage(problem.contact, reference.interface, hat);
  hat.lambda *= 0.7;  // an iterate away from the solution
  global.solve(hat, s);
  for (const stc::InterfaceHistory* iterate : {&reference.interface, static_cast<const stc::InterfaceHistory*>(&s)}) {
    const double expected =
        stc::spaceTimeEnergy(problem, stc::freeDisplacements(problem, K, iterate->lambda));
    EXPECT_NEAR(energy(*iterate), expected, 1e-9 * expected);
  }
}
