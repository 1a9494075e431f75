// Contact interface of a 3D scene (docs/method.md §1, "Three dimensions"): three rows per node, the
// frame (n, τ_1, τ_2), tributary areas, B and the search direction on the half-ball.
#include <gtest/gtest.h>

#include "src/mesh/facet_measure.hpp"
#include "src/problem/problem.hpp"
#include "solver/hemisphere_scene.hpp"

namespace {

const stc::Problem& hemisphere() {
  static const stc::Problem problem = stc::buildProblem(stc::test::hemisphereScene(4, 3));
  return problem;
}

}  // namespace

TEST(ContactInterface3d, HasThreeRowsPerNodeAndLeavesTheDrivenRimOut) {
  const auto& p = hemisphere();
  EXPECT_EQ(p.contact.dimension, 3);
  EXPECT_EQ(p.contact.B.rows(), 3 * p.contact.size());
  for (int node : p.contact.nodes) EXPECT_LT(p.solid.nodes(2, node), 0.0);  // the rim (z = 0) is driven
  EXPECT_LT(p.contact.size(), static_cast<int>(p.solid.group("contact").nodes.size()));
}

TEST(ContactInterface3d, FrameIsTheNormalAndTheCoordinateAxesOfItsPlane) {
  const auto& c = hemisphere().contact;
  for (int i = 0; i < c.size(); ++i) {
    EXPECT_EQ(Eigen::Vector3d(c.normals.col(i)), Eigen::Vector3d(0, 0, 1));
    EXPECT_EQ(Eigen::Vector3d(c.tangents.col(2 * i)), Eigen::Vector3d(1, 0, 0));      // τ_1 = e_x
    EXPECT_EQ(Eigen::Vector3d(c.tangents.col(2 * i + 1)), Eigen::Vector3d(0, 1, 0));  // τ_2 = n × τ_1
  }
}

TEST(ContactInterface3d, FrameOfATiltedPlaneIsRightHandedAndOrthonormal) {
  stc::Scene scene = stc::test::hemisphereScene(3, 3);
  scene.obstacle.normal = Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0;
  scene.obstacle.point = Eigen::Vector3d(-3.0, -3.0, -3.0);
  const stc::Problem p = stc::buildProblem(scene);
  Eigen::Matrix3d frame;
  frame << p.contact.tangents.col(0), p.contact.tangents.col(1), p.contact.normals.col(0);
  EXPECT_LT((frame.transpose() * frame - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(frame.determinant(), 1.0, 1e-15);
}

// Every triangle of the group gives a third of its area to each node; the nodes left out (the rim)
// keep theirs: the contact nodes' areas and the rim's add up to the group's area.
TEST(ContactInterface3d, TributaryAreasAddUpToTheGroupArea) {
  const auto& p = hemisphere();
  const auto& group = p.solid.group("contact");
  double total = 0.0, rim = 0.0;
  for (const auto& t : group.triangles) {
    const double area = stc::facetMeasure(p.solid.nodes, t);
    total += area;
    for (int node : t)
      if (p.solid.nodes(2, node) == 0.0) rim += area / 3.0;
  }
  EXPECT_NEAR(p.contact.tributary.sum() + rim, total, 1e-12 * total);
  EXPECT_NEAR(total, 2.0 * M_PI, 0.05 * 2.0 * M_PI);  // the hemisphere's area, to its faceting
}

TEST(ContactInterface3d, BTakesTheNormalAndTangentialComponentsAndKIsTheSameOnTheThreeRows) {
  const auto& p = hemisphere();
  const int i = p.contact.size() / 2, node = p.contact.nodes[i];
  Eigen::VectorXd u = Eigen::VectorXd::Zero(p.numFreeDofs());
  u[p.free_index[3 * node]] = 0.3;
  u[p.free_index[3 * node + 1]] = -0.7;
  u[p.free_index[3 * node + 2]] = 0.2;
  const Eigen::VectorXd v = p.contact.B * u;
  EXPECT_DOUBLE_EQ(v[3 * i], 0.2);
  EXPECT_DOUBLE_EQ(v[3 * i + 1], 0.3);
  EXPECT_DOUBLE_EQ(v[3 * i + 2], -0.7);
  EXPECT_DOUBLE_EQ(v.cwiseAbs().sum(), 1.2);
  for (int r = 0; r < 3; ++r)
    EXPECT_DOUBLE_EQ(p.contact.search_direction[3 * i + r], 4.0 * 3000.0 * p.contact.tributary[i] / 1.0);
}
