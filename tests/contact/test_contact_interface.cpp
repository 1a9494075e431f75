// Contact interface of docs/method.md §1: frames, gaps, tributary lengths, B and the search direction.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "fixtures/seed_scene.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/problem/problem.hpp"

namespace {

const stc::Problem& seed() {
  static const stc::Problem problem = stc::buildProblem(stc::test::seedScene(101, 3));
  return problem;
}

}  // namespace

TEST(ContactInterface, SeedHasTheArcNodesWithoutTheDrivenCorners) {
  const auto& c = seed().contact;
  EXPECT_EQ(c.size(), 101);
  for (int node : c.nodes) EXPECT_LT(std::get<stc::TriMesh>(seed().body).nodes(1, node), 0.0);  // corners (y = 0) excluded
}

TEST(ContactInterface, FrameIsTheObstacleNormalAndItsRotation) {
  const auto& c = seed().contact;
  for (int i = 0; i < c.size(); ++i) {
    EXPECT_EQ(c.normals.col(i), Eigen::Vector2d(0.0, 1.0));
    EXPECT_EQ(c.tangents.col(i), Eigen::Vector2d(1.0, 0.0));  // τ = (n_y, −n_x)
  }
}

TEST(ContactInterface, InitialGapIsTheDistanceToThePlane) {
  const auto& p = seed();
  for (int i = 0; i < p.contact.size(); ++i)
    EXPECT_NEAR(p.contact.initial_gap[i], std::get<stc::TriMesh>(p.body).nodes(1, p.contact.nodes[i]) + 1.01, 1e-15);
  EXPECT_NEAR(p.contact.initial_gap.minCoeff(), 0.01, 1e-15);  // the lowest arc node at (0, −1)
}

TEST(ContactInterface, TributaryLengthsAddUpToTheArcMinusTheCornerHalves) {
  // 102 equal chords of the arc; the two corner nodes are not contact nodes and keep half an edge each.
  const auto& c = seed().contact;
  const double chord = 2.0 * std::sin(std::numbers::pi / (2 * 102));
  EXPECT_NEAR(c.tributary.sum(), 101 * chord, 1e-12);
  EXPECT_NEAR(c.tributary.maxCoeff(), chord, 1e-12);
}

TEST(ContactInterface, BRestrictsAndRotatesTheNodalDisplacement) {
  const auto& p = seed();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(p.numFreeDofs());
  const int i = 50, node = p.contact.nodes[i];
  u[p.free_index[2 * node]] = 0.3;
  u[p.free_index[2 * node + 1]] = -0.7;
  const Eigen::VectorXd v = p.contact.B * u;
  EXPECT_DOUBLE_EQ(v[2 * i], -0.7);  // n·u
  EXPECT_DOUBLE_EQ(v[2 * i + 1], 0.3);  // τ·u
  EXPECT_EQ(v.cwiseAbs().sum(), 1.0);
}

TEST(ContactInterface, SearchDirectionScalesWithTributaryLength) {
  stc::Scene scene = stc::test::seedScene(31, 3);
  scene.search_direction.scale = 2.5;
  scene.search_direction.law = stc::SearchLaw::Tributary;
  const stc::Problem p = stc::buildProblem(scene);
  for (int i = 0; i < p.contact.size(); ++i) {
    const double expected = 2.5 * 3000.0 * p.contact.tributary[i] / 1.0;  // κ E ℓ_i / L, L = radius
    EXPECT_DOUBLE_EQ(p.contact.search_direction[2 * i], expected);
    EXPECT_DOUBLE_EQ(p.contact.search_direction[2 * i + 1], expected);
  }
}

TEST(ContactInterface, TiltedPlaneGivesRotatedFrame) {
  stc::Scene scene = stc::test::seedScene(31, 3);
  scene.obstacle.normal = Eigen::Vector2d(1.0, 1.0);
  scene.obstacle.point = Eigen::Vector2d(-2.0, -2.0);
  const stc::Problem p = stc::buildProblem(scene);
  const double s = std::sqrt(0.5);
  EXPECT_NEAR(p.contact.normals(0, 0), s, 1e-15);
  EXPECT_NEAR(p.contact.tangents(0, 0), s, 1e-15);
  EXPECT_NEAR(p.contact.tangents(1, 0), -s, 1e-15);
}

TEST(ContactInterface, PenetratingNodeIsAnInputError) {
  stc::Scene scene = stc::test::seedScene(31, 3);
  scene.obstacle.point = Eigen::Vector2d(0.0, -0.99);
  try {
    stc::buildProblem(scene);
    FAIL() << "penetration accepted";
  } catch (const stc::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("starts inside the obstacle"), std::string::npos) << e.what();
  }
}

TEST(ContactInterface, RestrictedToNodesKeepsTheirDataAndRowsInTheGivenOrder) {
  stc::ContactInterface full = seed().contact;
  full.held_rows = {2 * 7 + 1};  // node 7's tangential row, as a symmetry plane would hold it
  const std::vector<int> picked = {7, 3};
  const stc::ContactInterface sub = stc::restrictToNodes(full, picked);
  ASSERT_EQ(sub.size(), 2);
  EXPECT_EQ(sub.dimension, 2);
  EXPECT_EQ(sub.friction, full.friction);
  const Eigen::MatrixXd B = full.B, subB = sub.B;
  ASSERT_EQ(subB.rows(), 4);
  for (int j = 0; j < 2; ++j) {
    const int i = picked[static_cast<size_t>(j)];
    EXPECT_EQ(sub.nodes[static_cast<size_t>(j)], full.nodes[static_cast<size_t>(i)]);
    EXPECT_EQ(sub.initial_gap[j], full.initial_gap[i]);
    EXPECT_EQ(sub.tributary[j], full.tributary[i]);
    EXPECT_EQ(sub.normals.col(j), full.normals.col(i));
    EXPECT_EQ(sub.tangents.col(j), full.tangents.col(i));
    EXPECT_EQ(sub.search_direction.segment(2 * j, 2), full.search_direction.segment(2 * i, 2));
    EXPECT_EQ(subB.middleRows(2 * j, 2), B.middleRows(2 * i, 2));
  }
  EXPECT_EQ(sub.held_rows, std::vector<int>({1}));
  EXPECT_EQ(stc::restrictToNodes(full, {}).rows(), 0);
  EXPECT_THROW(stc::restrictToNodes(full, {full.size()}), std::out_of_range);
}

// The local law (src/options/search_direction_options.hpp) is the tributary one where every facet has one size:
// on the seed's uniform arc each interior node's k is the same to round-off, the two end nodes (half a
// patch) keep half of it, as with the tributary law.
TEST(ContactInterface, LocalSearchLawIsTheTributaryOneOnAUniformArc) {
  stc::Scene scene = stc::test::seedScene(31, 3);
  const stc::Problem tributary = stc::buildProblem(scene);
  scene.search_direction.law = stc::SearchLaw::Local;
  const stc::Problem local = stc::buildProblem(scene);
  const Eigen::VectorXd& k = local.contact.search_direction;
  EXPECT_NEAR((k - tributary.contact.search_direction).norm(), 0.0, 1e-12 * k.norm());
  EXPECT_NEAR(local.contact.facet_size.maxCoeff(), local.contact.facet_size.minCoeff(),
              1e-9 * local.contact.facet_size.maxCoeff());
}

// On a 2D boundary of two edge sizes the local law gives an interior node the same k whatever the
// size of its edges (a plane body's local stiffness does not grow with the patch), k_i ∝ ℓ_i / h_i,
// and keeps the tributary law's total.
TEST(ContactInterface, LocalSearchLawFollowsTributaryOverFacetSize) {
  stc::ContactInterface c;
  c.dimension = 2;
  c.nodes = {0, 1, 2, 3};
  c.tributary = Eigen::Vector4d(0.5, 1.0, 1.5, 1.0);   // edges of length 1, 1, 2 between the nodes
  c.facet_size = Eigen::Vector4d(1.0, 1.0, 1.5, 2.0);  // the mean length of the edges at each node
  stc::setSearchDirection(c, 4.0, 3000.0, 1.0, stc::SearchLaw::Local);
  const double total = 4.0 * 3000.0 * c.tributary.sum();
  const Eigen::Vector4d ratio = c.tributary.cwiseQuotient(c.facet_size);  // 0.5, 1, 1, 0.5
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(c.search_direction[2 * i], total * ratio[i] / ratio.sum(), 1e-12 * total) << i;
    EXPECT_EQ(c.search_direction[2 * i + 1], c.search_direction[2 * i]) << i;
  }
  EXPECT_NEAR(c.search_direction[2], c.search_direction[4], 1e-12 * total);  // interior nodes alike
}
