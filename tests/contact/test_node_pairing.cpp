// Node-to-node pairs of two bodies (src/contact/node_pairing.hpp, buildContactPair): the pair's
// normal, gap and B rows n·(u_s − u_m), and the checks that refuse boundaries that do not match.
#include <gtest/gtest.h>

#include "fixtures/seed_scene.hpp"
#include "fixtures/two_bodies_scene.hpp"
#include "stcontact/contact/node_pairing.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/problem/problem.hpp"

namespace {

const stc::Problem& pair() {
  static const stc::Problem problem = stc::buildProblem(stc::test::mirroredPair(stc::test::seedScene(21, 3)));
  return problem;
}

TEST(NodePairing, MirroredArcsPairAlongTheCommonNormalWithTwiceTheGapToTheFlat) {
  const stc::ContactInterface& c = pair().contact;
  const auto& mesh = std::get<stc::TriMesh>(pair().body);
  ASSERT_TRUE(c.isPair());
  ASSERT_EQ(c.size(), 21);
  for (int i = 0; i < c.size(); ++i) {
    const int s = c.nodes[i], m = c.master_nodes[i];
    EXPECT_EQ(mesh.nodes(0, m), mesh.nodes(0, s));
    EXPECT_EQ(c.normals.col(i), Eigen::Vector2d(0.0, 1.0));
    EXPECT_NEAR(c.initial_gap[i], mesh.nodes(1, s) - mesh.nodes(1, m), 1e-15);
    EXPECT_NEAR(c.initial_gap[i], 2.0 * (mesh.nodes(1, s) + 1.01), 1e-14);
  }
}

// Row 2i of B is n·u_s − n·u_m: +1 on the slave's free y dof, −1 on the master's.
TEST(NodePairing, TheNormalRowTakesTheRelativeDisplacement) {
  const stc::Problem& p = pair();
  const int i = 10, s = p.contact.nodes[i], m = p.contact.master_nodes[i];
  const Eigen::MatrixXd B = Eigen::MatrixXd(p.contact.B);
  EXPECT_EQ(B(2 * i, p.free_index[2 * s + 1]), 1.0);
  EXPECT_EQ(B(2 * i, p.free_index[2 * m + 1]), -1.0);
  EXPECT_EQ(B.row(2 * i).cwiseAbs().sum(), 2.0);
  EXPECT_EQ(B(2 * i + 1, p.free_index[2 * s]), 1.0);  // τ = (n_y, −n_x) = (1, 0)
  EXPECT_EQ(B(2 * i + 1, p.free_index[2 * m]), -1.0);
}

// Two unit squares' facing edges with coincident nodes: without a common normal each slave node
// pairs with the master node at its place, gap 0, along the master's outward normal.
TEST(NodePairing, CoincidentNodesPairAlongTheMastersOutwardNormal) {
  Eigen::MatrixXd x(2, 4);
  x << 0.0, 1.0, 0.0, 1.0,  //
      0.0, 0.0, 0.0, 0.0;
  const Eigen::MatrixXd master_normals = Eigen::Vector2d(0.0, 1.0).replicate(1, 2);
  const auto pairs = stc::pairNodes(x, {0, 1}, {2, 3}, master_normals, Eigen::VectorXd());
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].master, 2);
  EXPECT_EQ(pairs[1].master, 3);
  EXPECT_EQ(pairs[0].gap, 0.0);
  EXPECT_EQ(pairs[1].normal, Eigen::VectorXd(Eigen::Vector2d(0.0, 1.0)));
}

TEST(NodePairing, RefusesASlaveBehindTheMasterBoundary) {
  Eigen::MatrixXd x(2, 2);
  x << 0.0, 0.0,  //
      -0.1, 0.0;  // the slave node 0.1 below the master's surface, whose normal points up
  const Eigen::MatrixXd up = Eigen::Vector2d(0.0, 1.0);
  EXPECT_THROW(stc::pairNodes(x, {0}, {1}, up, Eigen::VectorXd()), stc::InputError);
  EXPECT_THROW(stc::pairNodes(x, {0}, {1}, up, Eigen::Vector2d(0.0, 1.0)), stc::InputError);
}

TEST(NodePairing, RefusesNonMatchingMeshes) {
  Eigen::MatrixXd x(2, 3);
  x << 0.0, 0.1, 0.05,  //
      0.1, 0.1, 0.0;    // two slave nodes over one master node
  const Eigen::MatrixXd up = Eigen::Vector2d(0.0, 1.0);
  EXPECT_THROW(stc::pairNodes(x, {0, 1}, {2}, up, Eigen::VectorXd()), stc::InputError);
  EXPECT_THROW(stc::pairNodes(x, {0, 1}, {2}, up, Eigen::Vector2d(0.0, 1.0)), stc::InputError);
}

}  // namespace
