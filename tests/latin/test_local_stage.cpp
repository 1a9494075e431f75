// LATIN local stage (docs/method.md §2): its output lies in Γ, follows the search direction exactly,
// and leaves an admissible state unchanged.
#include <gtest/gtest.h>

#include <random>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/contact_law_check.hpp"

namespace {

// A random interface state of the size of the problem, with displacements at the scale of the seed
// scene's gap (0.01) and forces at `force_scale` (1 on the seed: k ~ 100, so k g0 ~ 1).
stc::InterfaceHistory randomState(const stc::Problem& problem, unsigned seed, double force_scale = 1.0) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  auto s = stc::InterfaceHistory::zeros(problem.contact, problem.numSteps());
  for (Eigen::Index j = 0; j < s.v.size(); ++j) {
    s.v(j) = 0.01 * normal(rng);
    s.lambda(j) = force_scale * normal(rng);
  }
  return s;
}

class LocalStageTest : public ::testing::Test {
 protected:
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(31, 21));
};

}  // namespace

TEST_F(LocalStageTest, OutputSatisfiesTheContactLawExactly) {
  for (unsigned seed : {1u, 2u, 3u}) {
    stc::InterfaceHistory hat;
    stc::latin::localStage(problem.contact, randomState(problem, seed), hat);
    // Exact up to one rounding of each arithmetic step: 1e-13 relative leaves a factor ~500 above ε.
    EXPECT_LE(stc::checkContactLaw(problem, hat).max(), 1e-13) << "seed " << seed;
  }
}

TEST_F(LocalStageTest, MovesAlongTheSearchDirection) {
  const stc::InterfaceHistory s = randomState(problem, 7);
  stc::InterfaceHistory hat;
  stc::latin::localStage(problem.contact, s, hat);
  const Eigen::VectorXd& k = problem.contact.search_direction;
  // λ̂ − λ = k (v̂ − v), entry by entry.
  const Eigen::MatrixXd mismatch = (hat.lambda - s.lambda) - k.asDiagonal() * (hat.v - s.v);
  EXPECT_LE(mismatch.cwiseAbs().maxCoeff(), 1e-12 * s.lambda.cwiseAbs().maxCoeff());
}

TEST_F(LocalStageTest, LeavesAnAdmissibleStateUnchanged) {
  stc::InterfaceHistory hat, again;
  stc::latin::localStage(problem.contact, randomState(problem, 11), hat);
  stc::latin::localStage(problem.contact, hat, again);  // a projection: applying it twice changes nothing
  EXPECT_LE((again.v - hat.v).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LE((again.lambda - hat.lambda).cwiseAbs().maxCoeff(), 1e-12);
}

TEST_F(LocalStageTest, OpenNodeKeepsNoForce) {
  // Far from the obstacle with a pulling force: the node opens, λ̂ = 0 and v̂ = v − λ/k.
  auto s = stc::InterfaceHistory::zeros(problem.contact, problem.numSteps());
  s.lambda.setConstant(-1.0);
  stc::InterfaceHistory hat;
  stc::latin::localStage(problem.contact, s, hat);
  EXPECT_EQ(hat.lambda.cwiseAbs().maxCoeff(), 0.0);
  const double k0 = problem.contact.search_direction[0];
  EXPECT_DOUBLE_EQ(hat.v(0, 0), 1.0 / k0);
}

TEST_F(LocalStageTest, SlipsWhenTrialLeavesConeAndSticksInside) {
  // One node pressed hard (closed) at every instant; a tangential displacement that grows fast
  // slips with λ̂_t = −μ λ̂_n sign(Δv̂_t), one that barely moves sticks.
  const double mu = problem.contact.friction, kt = problem.contact.search_direction[1];
  auto s = stc::InterfaceHistory::zeros(problem.contact, problem.numSteps());
  s.v.row(0).setConstant(-problem.contact.initial_gap[0]);  // at the obstacle
  s.lambda.row(0).setConstant(10.0);                          // pressed
  for (int k = 0; k < problem.numSteps(); ++k) s.v(1, k) = 1.0 * k;  // large tangential motion
  stc::InterfaceHistory hat;
  stc::latin::localStage(problem.contact, s, hat);
  for (int k = 1; k < problem.numSteps(); ++k) {
    EXPECT_NEAR(std::abs(hat.lambda(1, k)), mu * hat.lambda(0, k), 1e-12) << "instant " << k;
    EXPECT_LT(hat.lambda(1, k) * (hat.v(1, k) - hat.v(1, k - 1)), 0.0) << "friction opposes slip at " << k;
  }
  s.v.row(1).setConstant(0.0);
  s.lambda.row(1).setConstant(0.5 * mu * 10.0);  // inside the cone, no motion: sticks
  stc::latin::localStage(problem.contact, s, hat);
  for (int k = 1; k < problem.numSteps(); ++k) EXPECT_EQ(hat.v(1, k), hat.v(1, k - 1));
  EXPECT_GT(kt, 0.0);
}

// In 3D the local stage projects on the Coulomb disc: the same two properties on random states of
// the half-ball's interface (three rows per node). Its gaps reach 0.78 and k ~ 600, so forces at
// scale 100 close the nodes near the pole and leave the others open.
TEST(LocalStage3d, OutputSatisfiesTheConeLawAndFollowsTheSearchDirection) {
  const stc::Problem problem = stc::buildProblem(stc::test::hemisphereScene(3, 11));
  for (unsigned seed : {1u, 2u}) {
    const stc::InterfaceHistory s = randomState(problem, seed, 100.0);
    stc::InterfaceHistory hat;
    stc::latin::localStage(problem.contact, s, hat);
    const Eigen::Map<const Eigen::MatrixXd> normal(hat.lambda.data(), 3, hat.lambda.size() / 3);
    const Eigen::Index closed = (normal.row(0).array() > 0.0).count();
    EXPECT_GT(closed, 0) << "seed " << seed;
    EXPECT_LT(closed, normal.cols()) << "seed " << seed;
    EXPECT_LE(stc::checkContactLaw(problem, hat).max(), 1e-13) << "seed " << seed;
    const Eigen::MatrixXd residual =
        (hat.lambda - s.lambda) - problem.contact.search_direction.asDiagonal() * (hat.v - s.v);
    EXPECT_LE(residual.cwiseAbs().maxCoeff(), 1e-12 * s.lambda.cwiseAbs().maxCoeff()) << "seed " << seed;
  }
}

namespace {

// localStageOfTrial against localStage on the stored trial s = (v0 + dv, w − k (v0 + dv)): the
// same arithmetic node by node, so the same bits (the coarse step's results do not change with it).
void expectTrialFormMatchesStoredTrial(const stc::Problem& problem) {
  const Eigen::VectorXd& k = problem.contact.search_direction;
  const stc::InterfaceHistory a = randomState(problem, 21), b = randomState(problem, 22);
  const Eigen::MatrixXd& v0 = a.v;
  const Eigen::MatrixXd dv = 0.1 * b.v, w = a.lambda + b.lambda;
  stc::InterfaceHistory trial{v0 + dv, Eigen::MatrixXd()};
  trial.lambda = w - k.asDiagonal() * trial.v;
  stc::InterfaceHistory expected, hat;
  stc::latin::localStage(problem.contact, trial, expected);
  const Eigen::MatrixXd expected_image = expected.lambda + k.asDiagonal() * expected.v;
  Eigen::MatrixXd image;
  stc::latin::localStageOfTrial(problem.contact, v0, dv, w, &hat, &image);
  EXPECT_TRUE(hat.v == expected.v);
  EXPECT_TRUE(hat.lambda == expected.lambda);
  EXPECT_TRUE(image == expected_image);
  // Either output alone: the same values.
  Eigen::MatrixXd image_alone;
  stc::InterfaceHistory hat_alone;
  stc::latin::localStageOfTrial(problem.contact, v0, dv, w, nullptr, &image_alone);
  stc::latin::localStageOfTrial(problem.contact, v0, dv, w, &hat_alone, nullptr);
  EXPECT_TRUE(image_alone == expected_image);
  EXPECT_TRUE(hat_alone.lambda == expected.lambda);
}

}  // namespace

TEST_F(LocalStageTest, TrialFormIsBitwiseTheLocalStageOfTheStoredTrial) {
  expectTrialFormMatchesStoredTrial(problem);
}

TEST(LocalStage3d, TrialFormIsBitwiseTheLocalStageOfTheStoredTrial) {
  expectTrialFormMatchesStoredTrial(stc::buildProblem(stc::test::hemisphereScene(3, 11)));
}
