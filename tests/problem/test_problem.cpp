// Problem assembly: Dirichlet elimination with time-dependent histories, separated loads, edge loads.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include "fixtures/seed_scene.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/problem/problem.hpp"

TEST(Problem, PrescribedDofsFollowTheirHistories) {
  const stc::Problem p = stc::buildProblem(stc::test::seedScene(31, 11));  // t_k = k/10
  const auto& top = std::get<stc::TriMesh>(p.body).group("top").nodes;
  EXPECT_EQ(p.numDofs() - p.numFreeDofs(), 2 * static_cast<int>(top.size()));
  const Eigen::VectorXd u = p.fullDisplacement(Eigen::VectorXd::Zero(p.numFreeDofs()), 6);  // t = 0.6
  for (int node : top) {
    EXPECT_NEAR(u[2 * node], 0.05 * (0.6 - 0.2) / 0.8, 1e-15);
    EXPECT_NEAR(u[2 * node + 1], -0.01 - 0.1 * (0.6 - 0.2) / 0.8, 1e-15);
  }
}

TEST(Problem, EliminationReproducesTheConstrainedSolve) {
  // Without contact forces, u_free(t) = K_ff⁻¹ f(t) must make the full K u vanish on free rows.
  const stc::Problem p = stc::buildProblem(stc::test::seedScene(31, 11));
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> llt(p.stiffness_free);
  for (int k : {0, 5, 10}) {
    const Eigen::VectorXd u = p.fullDisplacement(llt.solve(p.load(k)), k);
    const Eigen::VectorXd r = p.stiffness * u;
    const double scale = 1e-12 * p.stiffness.norm() * u.norm();  // round-off of K u
    for (int dof : p.free_dofs) EXPECT_LE(std::abs(r[dof]), scale) << "instant " << k;
  }
  // Separated storage: loadBlock equals the column-by-column loads.
  const Eigen::MatrixXd F = p.loadBlock(3, 4);
  for (int j = 0; j < 4; ++j) EXPECT_LE((F.col(j) - p.load(3 + j)).norm(), 1e-14 * F.norm());
}

TEST(Problem, EdgeLoadSpreadsTheTotalForceByEdgeLength) {
  // A total force F(t) on the arc: 102 equal chords, so each interior node gets F/102 and each
  // corner F/204; the corners are prescribed (on top), so the free part sums to F (1 − 1/102).
  stc::Scene scene = stc::test::seedScene(101, 3);
  scene.loads.push_back({"arc", stc::Component::Y, {{0.0, 1.0}, {0.0, -5.0}}});
  const stc::Problem p = stc::buildProblem(scene);
  const stc::SeparatedLoad& load = p.loads.back();
  EXPECT_NEAR(load.free_force.sum(), 1.0 - 1.0 / 102.0, 1e-12);
  EXPECT_NEAR(load.free_force.maxCoeff(), 1.0 / 102.0, 1e-12);
  EXPECT_EQ(load.prescribed.norm(), 0.0);
  EXPECT_DOUBLE_EQ(load.values[1], -2.5);  // t = 0.5
}

TEST(Problem, HalfPrescribedContactNodeIsAnInputError) {
  stc::Scene scene = stc::test::seedScene(31, 3);
  scene.dirichlet.pop_back();  // top: only u_x prescribed
  scene.contact.boundary = "top";
  EXPECT_THROW(stc::buildProblem(scene), stc::InputError);
}

TEST(Problem, DofPrescribedTwiceIsAnInputError) {
  stc::Scene scene = stc::test::seedScene(31, 3);
  scene.dirichlet.push_back({"top", stc::Component::X, {{0.0}, {0.0}}});
  try {
    stc::buildProblem(scene);
    FAIL();
  } catch (const stc::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("already prescribed by dirichlet[0]"), std::string::npos) << e.what();
  }
}
