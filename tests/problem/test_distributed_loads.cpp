// Pressure and body-force patterns (src/problem/distributed_loads.hpp) against their resultants: a
// pressure on a closed boundary has none, on the half-disc's flat top it is −p · length along the
// outward normal, on the half-ball's top −p · area; a body force's total is its value times the
// body's measure. Then the scene keys: a [[load]] of type pressure or body reaches the problem.
#include <gtest/gtest.h>

#include <cmath>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/mesh/facet_measure.hpp"
#include "stcontact/problem/distributed_loads.hpp"
#include "stcontact/problem/problem.hpp"

namespace {

// The sum of a pattern's components along each axis.
Eigen::VectorXd resultant(const Eigen::VectorXd& pattern, int d) {
  return pattern.reshaped(d, pattern.size() / d).rowwise().sum();
}

const stc::Problem& seed() {
  static const stc::Problem p = stc::buildProblem(stc::test::seedScene(41, 3));
  return p;
}

const stc::Problem& hemisphere() {
  static const stc::Problem p = stc::buildProblem(stc::test::hemisphereScene(4, 3));
  return p;
}

}  // namespace

TEST(DistributedLoads, PressureOnTheFlatTopIsMinusItsLengthAlongTheOutwardNormal) {
  const auto& mesh = std::get<stc::TriMesh>(seed().body);
  const Eigen::VectorXd top = stc::pressurePattern(mesh, "top"), arc = stc::pressurePattern(mesh, "arc");
  EXPECT_NEAR(resultant(top, 2)[0], 0.0, 1e-14);
  EXPECT_NEAR(resultant(top, 2)[1], -2.0, 1e-14);  // the top y = 0 from x = −1 to 1, outward +y
  // The top and the arc close the boundary: a uniform pressure on all of it has no resultant.
  EXPECT_LE(resultant(top + arc, 2).norm(), 1e-13);
  EXPECT_NEAR(resultant(arc, 2)[1], 2.0, 1e-13);  // the arc's chord, pushed up
}

TEST(DistributedLoads, PressureOnTheHalfBallsTopIsMinusItsArea) {
  const auto& mesh = std::get<stc::TetMesh>(hemisphere().body);
  const Eigen::VectorXd top = stc::pressurePattern(mesh, "top"), curved = stc::pressurePattern(mesh, "contact");
  double area = 0.0;
  for (const auto& t : mesh.group("top").triangles) area += stc::facetMeasure(mesh.nodes, t);
  EXPECT_NEAR(resultant(top, 3)[2], -area, 1e-13 * area);
  EXPECT_NEAR(area, M_PI, 0.1);  // the polygon inscribed in the unit disc
  EXPECT_LE(resultant(top + curved, 3).norm(), 1e-12);
}

TEST(DistributedLoads, BodyForceTotalIsTheBodysMeasure) {
  const auto& disc = std::get<stc::TriMesh>(seed().body);
  double area = 0.0;
  for (int e = 0; e < disc.numElements(); ++e) area += 0.5 * std::abs(disc.twiceSignedArea(e));
  const Eigen::VectorXd down = stc::bodyForcePattern(disc, stc::Component::Y);
  EXPECT_NEAR(resultant(down, 2)[1], area, 1e-12);
  EXPECT_EQ(resultant(down, 2)[0], 0.0);
  EXPECT_NEAR(area, M_PI / 2, 0.01);
  const auto& ball = std::get<stc::TetMesh>(hemisphere().body);
  double volume = 0.0;
  for (int e = 0; e < ball.numElements(); ++e) volume += std::abs(ball.sixSignedVolume(e)) / 6.0;
  EXPECT_NEAR(resultant(stc::bodyForcePattern(ball, stc::Component::Z), 3)[2], volume, 1e-12);
}

TEST(DistributedLoads, PressureAndBodyLoadsOfASceneReachTheProblem) {
  stc::Scene scene = stc::test::seedScene(41, 3);
  stc::LoadSpec pressure{"arc", stc::Component::X, {{0.0}, {2.0}}, stc::LoadKind::Pressure};
  stc::LoadSpec gravity{"", stc::Component::Y, {{0.0}, {-0.5}}, stc::LoadKind::Body};
  scene.loads = {pressure, gravity};
  const stc::Problem p = stc::buildProblem(scene);
  const std::size_t first = scene.dirichlet.size();  // the Dirichlet terms come first
  ASSERT_EQ(p.loads.size(), first + 2);
  const auto& mesh = std::get<stc::TriMesh>(p.body);
  const Eigen::VectorXd arc = stc::pressurePattern(mesh, "arc"), body = stc::bodyForcePattern(mesh, stc::Component::Y);
  for (int i = 0; i < p.numFreeDofs(); ++i) {
    EXPECT_EQ(p.loads[first].free_force[i], arc[p.free_dofs[i]]);
    EXPECT_EQ(p.loads[first + 1].free_force[i], body[p.free_dofs[i]]);
  }
  EXPECT_EQ(p.loads[first].values, std::vector<double>(3, 2.0));
  EXPECT_EQ(p.loads[first + 1].values, std::vector<double>(3, -0.5));
}
