// Node-to-segment pairs of two bodies with non-matching interface meshes (src/contact/node_pairing.hpp,
// pairNodesToFacets; contact.pairing = "segment"): the projection's weights, gap and B rows, the same
// pairs as node to node where the meshes match, and the refusals.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "fixtures/two_bodies_scene.hpp"
#include "stcontact/contact/node_pairing.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace {

const Eigen::VectorXd kUp2 = Eigen::Vector2d(0.0, 1.0);

// Master edge from (1, 0) to (0, 0): outward normal (t_y, −t_x) = (0, 1), toward the slaves above.
Eigen::MatrixXd edgeAndSlave(double x, double y) {
  Eigen::MatrixXd positions(2, 3);
  positions << 1.0, 0.0, x,  //
      0.0, 0.0, y;
  return positions;
}

TEST(NodeToSegment, ASlaveAboveAnEdgePairsWithItsPointByBarycentricWeights) {
  const auto pairs = stc::pairNodesToFacets(edgeAndSlave(0.25, 0.1), {2}, {{0, 1}}, kUp2);
  ASSERT_EQ(pairs.size(), 1u);
  ASSERT_EQ(pairs[0].facet, (std::vector<int>{0, 1}));
  EXPECT_NEAR(pairs[0].weights[0], 0.25, 1e-15);  // p = 0.25 (1, 0) + 0.75 (0, 0)
  EXPECT_NEAR(pairs[0].weights[1], 0.75, 1e-15);
  EXPECT_EQ(pairs[0].master, 1);  // the larger weight
  EXPECT_NEAR(pairs[0].gap, 0.1, 1e-15);
  EXPECT_EQ(pairs[0].normal, kUp2);
}

// Right above a master node the other weight is exactly 0 and dropped: node to node.
TEST(NodeToSegment, ASlaveAboveAMasterNodePairsWithThatNodeAlone) {
  const auto pairs = stc::pairNodesToFacets(edgeAndSlave(0.0, 0.2), {2}, {{0, 1}}, kUp2);
  ASSERT_EQ(pairs[0].facet, std::vector<int>{1});
  EXPECT_EQ(pairs[0].weights, std::vector<double>{1.0});
}

// A triangle seen along z: the weights are the point's barycentric coordinates.
TEST(NodeToSegment, ASlaveAboveATrianglePairsWithItsPoint) {
  Eigen::MatrixXd positions(3, 4);
  positions << 0.0, 1.0, 0.0, 0.2,  //
      0.0, 0.0, 1.0, 0.3,           //
      0.0, 0.0, 0.0, 0.5;
  const auto pairs = stc::pairNodesToFacets(positions, {3}, {{0, 1, 2}}, Eigen::Vector3d(0.0, 0.0, 1.0));
  ASSERT_EQ(pairs[0].facet, (std::vector<int>{0, 1, 2}));
  EXPECT_NEAR(pairs[0].weights[0], 0.5, 1e-15);
  EXPECT_NEAR(pairs[0].weights[1], 0.2, 1e-15);
  EXPECT_NEAR(pairs[0].weights[2], 0.3, 1e-15);
  EXPECT_NEAR(pairs[0].gap, 0.5, 1e-15);
}

TEST(NodeToSegment, RefusesASlaveBeyondBehindOrFacingAway) {
  const auto refused = [](const Eigen::MatrixXd& x, std::vector<int> edge) {
    try {
      stc::pairNodesToFacets(x, {2}, {std::move(edge)}, kUp2);
    } catch (const stc::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refused(edgeAndSlave(1.5, 0.1), {0, 1}).find("slave node 2 at (1.5, 0.1) meets no master facet"), std::string::npos);
  EXPECT_NE(refused(edgeAndSlave(0.5, -0.1), {0, 1}).find("meets no master facet"), std::string::npos);  // behind
  EXPECT_NE(refused(edgeAndSlave(0.5, 0.1), {1, 0}).find("meets no master facet"), std::string::npos);   // facing away
  EXPECT_EQ(refused(edgeAndSlave(0.5, 0.1), {0, 1}), "");
}

// On matching meshes (the seed body and its mirror image) node to segment finds node to node's pairs:
// the same master nodes with weight exactly 1, the same gaps, the same B.
void expectNodeToNode(stc::Scene scene) {
  ASSERT_GT(scene.contact.normal.size(), 0);
  const stc::Problem nodes = stc::buildProblem(scene);
  scene.contact.to_segment = true;
  const stc::Problem segments = stc::buildProblem(scene);
  EXPECT_EQ(segments.contact.master_nodes, nodes.contact.master_nodes);
  EXPECT_EQ(segments.contact.master_weights.cwiseAbs().colwise().sum(), Eigen::RowVectorXd::Ones(nodes.contact.size()));
  EXPECT_EQ(segments.contact.initial_gap, nodes.contact.initial_gap);
  EXPECT_EQ(Eigen::MatrixXd(segments.contact.B), Eigen::MatrixXd(nodes.contact.B));
}

TEST(NodeToSegment, OnMatchingMeshesItIsNodeToNode) {
  expectNodeToNode(stc::test::mirroredPair(stc::test::seedScene(21, 3)));
  expectNodeToNode(stc::test::mirroredPair(stc::test::hemisphereScene(4, 3)));  // triangles
}

// The fretting pad on non-matching faces (the specimen's nodes 0.013 apart under the pad's 0.02): a
// slave node between two master nodes has the normal row n·u_s − w_a n·u_a − w_b n·u_b, Σ w = 1.
TEST(NodeToSegment, TheNormalRowTakesTheWeightedMasterDisplacement) {
  const auto file = std::filesystem::path(STC_SOURCE_DIR) / "examples/scenes/fretting_pad.toml";
  const stc::Problem p = stc::buildProblem(
      stc::readScene(file, {"mesh.file=../meshes/fretting_pad_nonmatching_small.msh", "contact.pairing=segment"}));
  const Eigen::MatrixXd B = Eigen::MatrixXd(p.contact.B);
  int between = 0;
  for (int i = 0; i < p.contact.size(); ++i) {
    double master_sum = 0.0;
    int masters = 0;
    for (; masters < p.contact.master_facets.rows() && p.contact.master_facets(masters, i) >= 0; ++masters)
      master_sum += B(2 * i, p.free_index[2 * p.contact.master_facets(masters, i) + 1]);
    between += masters == 2 ? 1 : 0;
    EXPECT_EQ(B(2 * i, p.free_index[2 * p.contact.nodes[i] + 1]), 1.0);
    EXPECT_NEAR(master_sum, -1.0, 1e-15) << i;
  }
  EXPECT_GE(between, p.contact.size() - 1);  // all but the slave node at x = 0, right above a master node
}

}  // namespace
