// The run's operators (src/operators/prepared_operators.hpp): each prepared once and handed out to
// every caller; a copy of the problem restricted to some contact nodes shares K_ff but has its own
// K_ff + Bᵀ k B; the operators are the matrices their names say; u(λ) (displacement.hpp) is in
// equilibrium.
#include "stcontact/operators/prepared_operators.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "fixtures/seed_scene.hpp"
#include "stcontact/operators/displacement.hpp"

namespace {

const stc::Problem& seedProblem() {
  static const stc::Problem problem = stc::buildProblem(stc::test::seedScene(21, 11));
  return problem;
}

// The problem on its first `count` contact nodes: the same body, another interface.
stc::Problem onFirstNodes(int count) {
  stc::Problem part = seedProblem();
  std::vector<int> nodes(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) nodes[static_cast<std::size_t>(i)] = i;
  part.contact = stc::restrictToNodes(part.contact, nodes);
  return part;
}

TEST(PreparedOperators, StiffnessIsPreparedOnceForEveryCaller) {
  stc::PreparedOperators operators;
  const auto first = operators.stiffnessFree(seedProblem());
  const auto again = operators.stiffnessFree(seedProblem(), {{0, 1, 2}, 0.0});  // another ordering: the same factor
  const auto of_part = operators.stiffnessFree(onFirstNodes(5));                  // a copy of the body
  EXPECT_EQ(first.get(), again.get());
  EXPECT_EQ(first.get(), of_part.get());
  const std::vector<stc::Preparation> prepared = operators.preparations();
  ASSERT_EQ(prepared.size(), 1u);
  EXPECT_EQ(prepared[0].name, "K_ff");
  EXPECT_EQ(prepared[0].rows, seedProblem().numFreeDofs());
  EXPECT_EQ(prepared[0].uses, 3);
  EXPECT_EQ(prepared[0].factor_nonzeros, first->factorNonZeros());
}

TEST(PreparedOperators, AnotherBodyIsRefused) {
  stc::PreparedOperators operators;
  operators.stiffnessFree(seedProblem());
  const stc::Problem other = stc::buildProblem(stc::test::seedScene(31, 11));
  EXPECT_THROW(operators.stiffnessFree(other), std::invalid_argument);
}

TEST(PreparedOperators, SearchOperatorIsPreparedOncePerInterfaceAndOrdering) {
  stc::PreparedOperators operators;
  const auto whole = operators.searchOperator(seedProblem());
  const auto whole_again = operators.searchOperator(seedProblem());
  const auto part = operators.searchOperator(onFirstNodes(5));
  const auto ordered = operators.searchOperator(seedProblem(), {stc::dofsReadBy(seedProblem().contact.B), 0.0});
  EXPECT_EQ(whole.get(), whole_again.get());
  EXPECT_NE(whole.get(), part.get());
  EXPECT_NE(whole.get(), ordered.get());
  const std::vector<stc::Preparation> prepared = operators.preparations();
  ASSERT_EQ(prepared.size(), 3u);
  EXPECT_EQ(prepared[0].uses, 2);
  EXPECT_EQ(prepared[0].contact_nodes, seedProblem().contact.size());
  EXPECT_EQ(prepared[1].contact_nodes, 5);
  EXPECT_EQ(prepared[2].uses, 1);
}

// K_ff + Bᵀ k B, entry by entry against the product written out.
TEST(PreparedOperators, SearchOperatorIsTheStiffnessPlusTheInterfacesPenalty) {
  const stc::Problem& p = seedProblem();
  const Eigen::SparseMatrix<double> B = p.contact.B;
  const Eigen::MatrixXd expected =
      Eigen::MatrixXd(p.stiffness_free) +
      Eigen::MatrixXd(B.transpose()) * p.contact.search_direction.asDiagonal() * Eigen::MatrixXd(B);
  stc::PreparedOperators operators;
  const Eigen::MatrixXd A(operators.searchOperator(p)->matrix);
  EXPECT_LE((A - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
}

// K_ff u(λ) = f + Bᵀ λ at every instant, to round-off; the one-instant form gives the same column.
TEST(Displacement, IsInEquilibriumWithTheLoadsAndTheForces) {
  const stc::Problem& p = seedProblem();
  const Eigen::MatrixXd lambda = Eigen::MatrixXd::Random(p.contact.rows(), p.numSteps());
  stc::PreparedOperators operators;
  const auto factor = operators.stiffnessFree(p);
  const Eigen::MatrixXd u = stc::freeDisplacements(p, *factor, lambda);
  Eigen::MatrixXd rhs = p.loadBlock(0, p.numSteps());
  rhs += p.contact.B.transpose() * lambda;
  const Eigen::MatrixXd residual = p.stiffness_free * u - rhs;
  EXPECT_LE(residual.cwiseAbs().maxCoeff(), 1e-10 * rhs.cwiseAbs().maxCoeff());
  stc::CholmodFactor::Workspace workspace;
  const int k = p.numSteps() - 1;
  const Eigen::VectorXd at_k = stc::freeDisplacementAt(p, *factor, lambda.col(k), k, workspace);
  EXPECT_LE((at_k - u.col(k)).cwiseAbs().maxCoeff(), 1e-12 * u.col(k).cwiseAbs().maxCoeff());
  const Eigen::MatrixXd full = stc::fullDisplacements(p, *factor, lambda);
  EXPECT_EQ(full.rows(), p.numDofs());
  EXPECT_EQ(full.col(k), p.fullDisplacement(u.col(k), k));
}

}  // namespace
