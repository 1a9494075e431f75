// Contact interface of a 3D scene (docs/method.md §1, "Three dimensions"): three rows per node, the
// frame (n, τ_1, τ_2), tributary areas, B and the search direction on the half-ball.
#include <gtest/gtest.h>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/slab_scene.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/facet_measure.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene.hpp"

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
  for (int node : p.contact.nodes) EXPECT_LT(std::get<stc::TetMesh>(p.body).nodes(2, node), 0.0);  // the rim (z = 0) is driven
  EXPECT_LT(p.contact.size(), static_cast<int>(std::get<stc::TetMesh>(p.body).group("contact").nodes.size()));
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
  const auto& group = std::get<stc::TetMesh>(p.body).group("contact");
  double total = 0.0, rim = 0.0;
  for (const auto& t : group.triangles) {
    const double area = stc::facetMeasure(std::get<stc::TetMesh>(p.body).nodes, t);
    total += area;
    for (int node : t)
      if (std::get<stc::TetMesh>(p.body).nodes(2, node) == 0.0) rim += area / 3.0;
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
  // The local law (the default): k_i = κ E ℓ_i h̄ / (L h_i), h̄ = Σ ℓ / Σ (ℓ / h), L = radius.
  const Eigen::VectorXd& l = p.contact.tributary;
  const double h_mean = l.sum() / l.cwiseQuotient(p.contact.facet_size).sum();
  const double expected = 4.0 * 3000.0 * l[i] * h_mean / (1.0 * p.contact.facet_size[i]);
  for (int r = 0; r < 3; ++r) EXPECT_NEAR(p.contact.search_direction[3 * i + r], expected, 1e-13 * expected);
}

// The slab (tests/fixtures/slab_scene.hpp): u_z = 0 on its faces. A contact node there keeps its
// three rows; its τ_2 = −e_z row is held (empty B row); the arc's corners, whose normal motion u_y
// is driven with the top, are left out as in 2D.
TEST(ContactInterface3d, NodesHeldAtZeroAlongATangentGetAHeldRow) {
  const stc::Problem p = stc::buildProblem(stc::test::slabScene(7, 3, 0.05, 2));
  const auto& c = p.contact;
  EXPECT_EQ(c.size(), 3 * 7);  // the arc's 7 inner nodes on each of the 3 node layers
  std::vector<int> expected;
  for (int i = 0; i < c.size(); ++i) {
    const double z = std::get<stc::TetMesh>(p.body).nodes(2, c.nodes[i]);
    if (z == 0.0 || z == 0.05) expected.push_back(3 * i + 2);
    EXPECT_NEAR(c.tangents(2, 2 * i + 1), -1.0, 1e-15) << "τ_2 = n × e_x = −e_z";
  }
  EXPECT_EQ(c.held_rows, expected);
  for (int row : c.held_rows) EXPECT_EQ(Eigen::SparseMatrix<double>(c.B.row(row)).norm(), 0.0) << row;
}

TEST(ContactInterface3d, APrescribedTangentialMotionOtherThanZeroIsRefused) {
  stc::Scene scene = stc::test::slabScene(7, 3, 0.05, 2);
  scene.dirichlet[3].history = {{0.0, 1.0}, {0.0, 0.001}};  // the front face moves along z
  try {
    stc::buildProblem(scene);
    FAIL() << "a contact node with a nonzero prescribed tangential motion was accepted";
  } catch (const stc::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has a prescribed displacement component z; a contact node may only"),
              std::string::npos)
        << e.what();
  }
}
