// Curved rigid obstacles (src/contact/obstacle.hpp): a ball the body lies outside of (sphere in 3D,
// cylinder in 2D) or inside of (a seat). Gaps and normals against their formulas, the contact
// interface built on them (the half-disc's arc on a cylinder and in a seat), and the node at the
// centre, where the normal is undefined.
#include <gtest/gtest.h>

#include <cmath>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/contact/obstacle.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/problem/problem.hpp"

namespace {

stc::ObstacleSpec ball(Eigen::VectorXd centre, double radius, bool inside) {
  stc::ObstacleSpec spec;
  spec.type = centre.size() == 3 ? stc::ObstacleType::Sphere : stc::ObstacleType::Cylinder;
  spec.centre = std::move(centre);
  spec.radius = radius;
  spec.inside = inside;
  return spec;
}

// The seed half-disc (R = 1, lowest arc node at (0, −1)) above a cylinder, or in a seat, 0.01 away.
stc::Scene seedOn(const stc::ObstacleSpec& obstacle) {
  stc::Scene scene = stc::test::seedScene(101, 3);
  scene.obstacle = obstacle;
  return scene;
}

}  // namespace

TEST(BallObstacle, GapIsTheDistanceToTheSphereAndTheNormalPointsIntoTheBody) {
  const stc::Obstacle outside = stc::makeObstacle(ball(Eigen::Vector3d(1.0, 2.0, 3.0), 0.5, false));
  const Eigen::Vector3d x(1.0, 2.0 + 0.3, 3.0 + 0.4);  // 0.5 from the centre: on the sphere
  EXPECT_NEAR(stc::obstacleGap(outside, x), 0.0, 1e-15);
  EXPECT_NEAR(stc::obstacleGap(outside, Eigen::Vector3d(1.0, 2.0, 5.0)), 1.5, 1e-15);
  EXPECT_TRUE(stc::obstacleNormal(outside, x).isApprox(Eigen::Vector3d(0.0, 0.6, 0.8), 1e-15));
  const stc::Obstacle seat = stc::makeObstacle(ball(Eigen::Vector3d(1.0, 2.0, 3.0), 2.0, true));
  EXPECT_NEAR(stc::obstacleGap(seat, x), 1.5, 1e-15);  // R − |x − c|
  EXPECT_TRUE(stc::obstacleNormal(seat, x).isApprox(Eigen::Vector3d(0.0, -0.6, -0.8), 1e-15));
  EXPECT_LT(stc::obstacleGap(seat, Eigen::Vector3d(1.0, 2.0, 5.5)), 0.0);  // beyond the seat: inside the obstacle
}

TEST(BallObstacle, TheHalfDiscOnACylinderHasGapsAndNormalsFromItsCentre) {
  const Eigen::Vector2d centre(0.0, -2.01);
  const stc::Problem p = stc::buildProblem(seedOn(ball(centre, 1.0, false)));
  const auto& nodes = std::get<stc::TriMesh>(p.body).nodes;
  for (int i = 0; i < p.contact.size(); ++i) {
    const Eigen::Vector2d r = nodes.col(p.contact.nodes[i]) - centre;
    EXPECT_NEAR(p.contact.initial_gap[i], r.norm() - 1.0, 1e-14);
    EXPECT_TRUE(p.contact.normals.col(i).isApprox(r.normalized(), 1e-14));
  }
  EXPECT_NEAR(p.contact.initial_gap.minCoeff(), 0.01, 1e-14);  // the lowest arc node, above the top
}

TEST(BallObstacle, TheHalfDiscInASeatHasGapsAndNormalsTowardTheCentre) {
  const Eigen::Vector2d centre(0.0, 0.99);  // radius 2: the seat's bottom at y = −1.01
  const stc::Problem p = stc::buildProblem(seedOn(ball(centre, 2.0, true)));
  const auto& nodes = std::get<stc::TriMesh>(p.body).nodes;
  for (int i = 0; i < p.contact.size(); ++i) {
    const Eigen::Vector2d r = nodes.col(p.contact.nodes[i]) - centre;
    EXPECT_NEAR(p.contact.initial_gap[i], 2.0 - r.norm(), 1e-14);
    EXPECT_TRUE(p.contact.normals.col(i).isApprox(-r.normalized(), 1e-14));
  }
  EXPECT_NEAR(p.contact.initial_gap.minCoeff(), 0.01, 1e-14);
}

TEST(BallObstacle, ANodeInsideTheObstacleOrAtItsCentreIsAnInputError) {
  EXPECT_THROW(stc::buildProblem(seedOn(ball(Eigen::Vector2d(0.0, -1.5), 1.0, false))), stc::InputError);  // overlaps
  const stc::Obstacle at_origin = stc::makeObstacle(ball(Eigen::Vector2d(0.0, 0.0), 1.0, false));
  EXPECT_THROW(stc::obstacleNormal(at_origin, Eigen::Vector2d(0.0, 0.0)), stc::InputError);
}

TEST(BallObstacle, TheHemisphereOnASphereTouchesAtItsPole) {
  stc::Scene scene = stc::test::hemisphereScene();
  scene.obstacle = ball(Eigen::Vector3d(0.0, 0.0, -3.01), 2.0, false);
  const stc::Problem p = stc::buildProblem(scene);
  Eigen::Index lowest = 0;
  EXPECT_NEAR(p.contact.initial_gap.minCoeff(&lowest), 0.01, 1e-12);
  EXPECT_TRUE(p.contact.normals.col(lowest).isApprox(Eigen::Vector3d(0.0, 0.0, 1.0), 1e-12));
}
