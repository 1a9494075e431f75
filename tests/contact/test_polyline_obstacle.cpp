// A rigid polyline (src/contact/obstacle.hpp, PolylineObstacle): gaps and normals from the closest
// point, a straight polyline is the plane, and a fine polyline on a circle is the cylinder within
// the chords' sagitta.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fixtures/seed_scene.hpp"
#include "stcontact/contact/obstacle.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/problem/problem.hpp"

namespace {

stc::PolylineObstacle line(std::initializer_list<double> xy) {
  const std::vector<double> v(xy);
  return {Eigen::Map<const Eigen::Matrix2Xd>(v.data(), 2, static_cast<Eigen::Index>(v.size() / 2))};
}

TEST(PolylineObstacle, SegmentsGiveTheirNormalAndVerticesThePointsDirection) {
  const stc::Obstacle ridge = line({-1.0, 0.0, 0.0, 1.0, 1.0, 0.0});  // a roof, the body above it
  // Above the left flank's middle: the flank's normal (−1, 1)/√2, the distance to its line.
  const Eigen::Vector2d flank(-0.5 - 0.1, 0.5 + 0.1);
  EXPECT_NEAR((stc::obstacleNormal(ridge, flank) - Eigen::Vector2d(-1.0, 1.0) / std::sqrt(2.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(stc::obstacleGap(ridge, flank), 0.1 * std::sqrt(2.0), 1e-15);
  // Straight above the apex: the closest point is the vertex, the normal points from it to the point.
  const Eigen::Vector2d above(0.0, 1.3);
  EXPECT_NEAR((stc::obstacleNormal(ridge, above) - Eigen::Vector2d(0.0, 1.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(stc::obstacleGap(ridge, above), 0.3, 1e-15);
  // Below the apex, inside the obstacle: a negative gap.
  EXPECT_LT(stc::obstacleGap(ridge, Eigen::Vector2d(0.0, 0.8)), 0.0);
  // Walking the other way puts the body below: the signs turn.
  const stc::Obstacle under = line({1.0, 0.0, 0.0, 1.0, -1.0, 0.0});
  EXPECT_NEAR(stc::obstacleGap(under, above), -0.3, 1e-15);
}

// The seed on a straight two-point polyline through the seed's flat: the plane's interface exactly.
TEST(PolylineObstacle, AStraightPolylineIsThePlane) {
  stc::Scene scene = stc::test::seedScene(31, 21);
  const stc::Problem plane = stc::buildProblem(scene);
  scene.obstacle.type = stc::ObstacleType::Polyline;
  scene.obstacle.points = line({-3.0, -1.01, 3.0, -1.01}).points;
  const stc::Problem poly = stc::buildProblem(scene);
  EXPECT_EQ(poly.contact.normals, plane.contact.normals);
  EXPECT_LE((poly.contact.initial_gap - plane.contact.initial_gap).cwiseAbs().maxCoeff(), 1e-15);
}

// The seed on a rigid cylinder of radius 1 (its top 0.01 below the disc) and on polylines through
// N points of that circle's upper third, walked left to right: the chords lie inside the circle by at
// most the sagitta s = R (1 − cos(Δθ/2)), so the polyline's gaps exceed the cylinder's by 0 … s and
// its normals turn by at most Δθ/2; the total normal force at the last instant follows to first order
// in Δθ (the normals are piecewise constant): measured −3.0e-3 at 61 points (Δθ = 0.035) and −5.4e-5
// at 2001 (Δθ = 0.00105), 0.086 and 0.052 Δθ; bound 0.1 Δθ.
TEST(PolylineObstacle, AFinePolylineOnACircleIsTheCylinderWithinTheSagitta) {
  stc::Scene scene = stc::test::seedScene(101, 3);
  scene.contact.friction = 0.0;
  scene.obstacle.type = stc::ObstacleType::Cylinder;
  scene.obstacle.centre = Eigen::Vector2d(0.0, -2.01);
  scene.obstacle.radius = 1.0;
  const stc::Problem cylinder = stc::buildProblem(scene);
  const stc::SolveResult on_cylinder = stc::solveIncremental(cylinder);
  const auto total = [](const stc::SolveResult& r) {
    double sum = 0.0;
    for (Eigen::Index row = 0; row < r.interface.lambda.rows(); row += 2) sum += r.interface.lambda(row, 2);
    return sum;
  };
  for (int n : {61, 2001}) {
    const double span = 2.0 * std::numbers::pi / 3.0, step = span / (n - 1);
    Eigen::Matrix2Xd points(2, n);
    for (int j = 0; j < n; ++j) {
      const double theta = 5.0 * std::numbers::pi / 6.0 - j * step;  // 150° down to 30°
      points.col(j) = Eigen::Vector2d(std::cos(theta), -2.01 + std::sin(theta));
    }
    scene.obstacle.type = stc::ObstacleType::Polyline;
    scene.obstacle.points = points;
    const stc::Problem poly = stc::buildProblem(scene);
    const double sagitta = 1.0 - std::cos(step / 2.0);
    for (int i = 0; i < poly.contact.size(); ++i) {
      const double excess = poly.contact.initial_gap[i] - cylinder.contact.initial_gap[i];
      EXPECT_GE(excess, -1e-14) << i;
      EXPECT_LE(excess, sagitta + 1e-14) << i;
      EXPECT_LE(std::acos(std::min(1.0, poly.contact.normals.col(i).dot(cylinder.contact.normals.col(i)))),
                step / 2.0 + 1e-7)
          << i;
    }
    const double relative = total(stc::solveIncremental(poly)) / total(on_cylinder) - 1.0;
    std::printf("[ measured ] %d points (sagitta %.2e): total normal force %+.2e relative to the cylinder's\n", n,
                sagitta, relative);
    EXPECT_LE(std::abs(relative), 0.1 * step) << n << " points";
  }
}

}  // namespace
