// A moving rigid obstacle (Problem::frame_motion, [[obstacle.motion]]): the problem is posed in the
// obstacle's frame, u' = u − d(t). Driving the body by w(t) against a fixed obstacle and moving the
// obstacle by −w(t) against the held body are the same relative motion: the same contact forces
// and gaps, and displacements that differ by the rigid translation w(t).
#include <gtest/gtest.h>

#include "fixtures/seed_scene.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/problem/problem.hpp"
#include "strategies/strategy_fixture.hpp"

namespace {

// The seed scene with its top held and the obstacle moved by minus the top's motion.
stc::Scene padDriven(stc::Scene scene) {
  for (stc::DirichletSpec& d : scene.dirichlet) {
    stc::History minus = d.history;
    for (double& v : minus.values) v = -v;
    scene.obstacle.motion.push_back({d.component, minus});
    d.history = {{0.0}, {0.0}};
  }
  return scene;
}

TEST(MovingObstacle, MovingTheObstacleIsDrivingTheBodyTheOtherWay) {
  const stc::Scene driven = stc::test::seedScene(31, 41);
  const stc::Problem body = stc::buildProblem(driven), pad = stc::buildProblem(padDriven(driven));
  ASSERT_EQ(pad.frame_motion.cols(), pad.numSteps());
  const stc::SolveResult a = stc::solveIncremental(body), b = stc::solveIncremental(pad);
  ASSERT_TRUE(a.summary.converged() && b.summary.converged());
  const double scale = a.interface.lambda.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  EXPECT_LE((a.interface.lambda - b.interface.lambda).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_LE((a.interface.v - b.interface.v).cwiseAbs().maxCoeff(), 1e-12 * a.interface.v.cwiseAbs().maxCoeff());
  // u_pad (scene frame) = u_body − w(t): the body held at its top, the obstacle moved by −w.
  const stc::CholmodFactor K(body.stiffness_free, "K");
  const int top = std::get<stc::TriMesh>(body.body).group("top").nodes.front();
  for (int k : {10, 25, 40}) {
    const Eigen::VectorXd f_a = body.load(k) + body.contact.B.transpose() * a.interface.lambda.col(k);
    const Eigen::VectorXd f_b = pad.load(k) + pad.contact.B.transpose() * b.interface.lambda.col(k);
    const Eigen::VectorXd u_a = body.absoluteDisplacement(K.solve(f_a), k);
    const Eigen::VectorXd u_b = pad.absoluteDisplacement(K.solve(f_b), k);
    const Eigen::Vector2d w = u_a.segment<2>(2 * top);
    EXPECT_EQ(u_b.segment<2>(2 * top), Eigen::Vector2d::Zero()) << k;  // the top is held
    EXPECT_EQ(pad.frame_motion.col(k), Eigen::Vector2d(-w)) << k;
    for (int node = 0; node < body.numNodes(); ++node)
      EXPECT_NEAR((u_a.segment<2>(2 * node) - w - u_b.segment<2>(2 * node)).cwiseAbs().maxCoeff(), 0.0, 1e-12) << node;
  }
}

// Every strategy on the pad-driven scene converges to the incremental solution within τ: they all
// work on the obstacle's frame, and no strategy code knows the obstacle moves.
TEST(MovingObstacle, EveryStrategyReachesTheIncrementalSolution) {
  const stc::test::StrategyFixture pad(padDriven(stc::test::seedScene(31, 41)));
  for (const std::string name : {"latin", "latin-pgd", "fas-aposteriori", "fas-apriori"}) {
    const stc::SolveResult r = pad.solve(name, 1e-6);
    ASSERT_TRUE(r.summary.converged()) << name << ": " << r.summary.message;
    ASSERT_TRUE(r.summary.error.has_value()) << name;
    EXPECT_LE(*r.summary.error, 1e-6) << name;
  }
}

// A fixed obstacle, or motion histories that are zero at every instant, leave the problem as it was.
TEST(MovingObstacle, AMotionThatIsZeroLeavesTheProblemUnchanged) {
  stc::Scene scene = stc::test::seedScene(31, 21);
  scene.obstacle.motion.push_back({stc::Component::Y, {{0.0, 1.0}, {0.0, 0.0}}});
  EXPECT_EQ(stc::buildProblem(scene).frame_motion.size(), 0);
}

}  // namespace
