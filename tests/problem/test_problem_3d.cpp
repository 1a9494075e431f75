// Problem assembly of 3D scenes: a Gmsh volume mesh (tests/mesh/data/cube.msh) with Dirichlet
// histories on a surface, face-area loads, and the interface on another surface, solved by the
// incremental solver and by LATIN to the same answer.
#include <gtest/gtest.h>

#include "stcontact/core/input_error.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/strategies/registry.hpp"

namespace {

// The unit cube above the rigid plane z = −0.01, its top driven down by 0.02 in total (0.01 past
// first contact), x and y of the top held; frictionless contact on the bottom face.
stc::Scene cubeScene() {
  stc::Scene scene;
  scene.name = "cube";
  scene.dimension = 3;
  scene.mesh.file = std::string(STC_SOURCE_DIR) + "/tests/mesh/data/cube.msh";
  scene.material = {3000.0, 0.3};
  scene.obstacle.point = Eigen::Vector3d(0.0, 0.0, -0.01);
  scene.obstacle.normal = Eigen::Vector3d(0.0, 0.0, 1.0);
  scene.contact.boundary = "bottom";
  scene.time.steps = 5;
  scene.dirichlet.push_back({"top", stc::Component::X, {{0.0}, {0.0}}});
  scene.dirichlet.push_back({"top", stc::Component::Y, {{0.0}, {0.0}}});
  scene.dirichlet.push_back({"top", stc::Component::Z, {{0.0, 1.0}, {0.0, -0.02}}});
  scene.output.frames = false;
  return scene;
}

}  // namespace

TEST(Problem3d, CubeFromAGmshFileHasItsSizesAndInterface) {
  const stc::Problem p = stc::buildProblem(cubeScene());
  EXPECT_EQ(p.dimension, 3);
  EXPECT_EQ(p.numNodes(), 8);
  EXPECT_EQ(p.numDofs(), 24);
  EXPECT_EQ(p.numFreeDofs(), 12);  // the bottom's four nodes
  EXPECT_EQ(p.contact.size(), 4);
  EXPECT_NEAR(p.contact.tributary.sum(), 1.0, 1e-15);  // the bottom face's area
  EXPECT_NEAR(p.contact.initial_gap.minCoeff(), 0.01, 1e-15);
  EXPECT_NEAR(p.length_scale, 0.5, 1e-15);  // a mesh file: half its largest extent
}

// The same body gets the same search direction however it was meshed: the Gmsh half-ball of radius 1
// (examples/meshes/half_ball_graded_small.msh, extent 2 along x and y) has the generator's L = R = 1.
TEST(Problem3d, AHalfBallFromAFileHasTheGeneratorsLengthScale) {
  const std::string scenes = std::string(STC_SOURCE_DIR) + "/examples/scenes/";
  const stc::Problem from_file = stc::buildProblem(
      stc::readScene(scenes + "half_ball_graded.toml", {"mesh.file=../meshes/half_ball_graded_small.msh"}));
  const stc::Problem generated = stc::buildProblem(stc::readScene(scenes + "hemisphere.toml", {"mesh.divisions=4"}));
  EXPECT_NEAR(generated.length_scale, 1.0, 1e-15);
  EXPECT_NEAR(from_file.length_scale, generated.length_scale, 1e-12);
  EXPECT_NEAR(from_file.contact.search_scale_per_length, generated.contact.search_scale_per_length, 1e-9);
}

// A total force on a face is shared by area: each triangle gives a third of its share to each node.
TEST(Problem3d, FaceLoadIsSpreadByArea) {
  stc::Scene scene = cubeScene();
  scene.dirichlet.pop_back();
  scene.dirichlet.push_back({"top", stc::Component::Z, {{0.0}, {0.0}}});
  scene.contact.boundary = "top";  // keep the bottom free for the load (its contact is irrelevant here)
  scene.obstacle.point = Eigen::Vector3d(0.0, 0.0, 2.0);
  scene.obstacle.normal = Eigen::Vector3d(0.0, 0.0, -1.0);
  scene.loads.push_back({"bottom", stc::Component::Z, {{0.0}, {-6.0}}});
  EXPECT_THROW(stc::buildProblem(scene), stc::InputError);  // the top is fully driven: no contact node
  scene.contact.boundary = "bottom";
  scene.obstacle.point = Eigen::Vector3d(0.0, 0.0, -0.01);
  scene.obstacle.normal = Eigen::Vector3d(0.0, 0.0, 1.0);
  const stc::Problem p = stc::buildProblem(scene);
  const Eigen::VectorXd f = p.load(0);
  // Bottom triangles (1, 2, 4) and (1, 3, 4) of area 1/2: nodes 1 and 4 (ids 0, 3) get 2 × 1/6 of the
  // total, nodes 2 and 3 (ids 1, 2) 1/6.
  const double shares[4] = {2.0, 1.0, 1.0, 2.0};
  for (int node = 0; node < 4; ++node) EXPECT_NEAR(f[p.free_index[3 * node + 2]], -6.0 * shares[node] / 6.0, 1e-14);
}

TEST(Problem3d, CubePressedOnThePlaneSolvesTheSameByIncrementalAndLatin) {
  const stc::Scene scene = cubeScene();
  const stc::Problem p = stc::buildProblem(scene);
  const stc::SolveResult incremental = stc::solveIncremental(p);
  ASSERT_TRUE(incremental.summary.converged()) << incremental.summary.message;
  stc::SolverSpec spec = scene.solver;
  spec.setTolerance(1e-9);
  const stc::SolveResult latin = stc::solve(stc::strategyNamed("latin"), p, spec, {});
  ASSERT_TRUE(latin.summary.converged()) << latin.summary.message;
  const Eigen::VectorXd a = incremental.interface.lambda.col(4), b = latin.interface.lambda.col(4);
  double normal = 0.0;
  for (int i = 0; i < 4; ++i) normal += a[3 * i];
  EXPECT_GT(normal, 0.0);
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-6 * a.cwiseAbs().maxCoeff());
}

// The local search law on the graded Gmsh half-ball: k_i ∝ ℓ_i / h_i with h_i the mean √area of the
// node's triangles, the tributary law's total kept, and the spread of k across the grading narrowed
// (k grows as h, not as h²).
TEST(Problem3d, LocalSearchLawOnAGradedHalfBallFollowsTheFacetSize) {
  const std::string scene_file = std::string(STC_SOURCE_DIR) + "/examples/scenes/half_ball_graded.toml";
  const std::vector<std::string> small = {"mesh.file=../meshes/half_ball_graded_small.msh"};
  stc::Scene scene = stc::readScene(scene_file, small);
  scene.search_direction.law = stc::SearchLaw::Tributary;
  const stc::Problem tributary = stc::buildProblem(scene);
  scene.search_direction.law = stc::SearchLaw::Local;
  const stc::Problem local = stc::buildProblem(scene);
  const stc::ContactInterface& c = local.contact;
  const Eigen::VectorXd k = Eigen::Map<const Eigen::MatrixXd>(c.search_direction.data(), 3, c.size()).row(0);
  const Eigen::VectorXd k_tributary =
      Eigen::Map<const Eigen::MatrixXd>(tributary.contact.search_direction.data(), 3, c.size()).row(0);
  EXPECT_NEAR(k.sum(), k_tributary.sum(), 1e-12 * k.sum());
  const Eigen::VectorXd per_size = c.tributary.cwiseQuotient(c.facet_size);
  for (int i = 0; i < c.size(); ++i) EXPECT_NEAR(k[i] / per_size[i], k[0] / per_size[0], 1e-12 * k[0] / per_size[0]);
  const auto spread = [](const Eigen::VectorXd& v) { return v.maxCoeff() / v.minCoeff(); };
  EXPECT_LT(spread(k), spread(k_tributary) / 3.0);  // the grading's factor in size, not in area
  EXPECT_GT(spread(k), 1.5);
}
