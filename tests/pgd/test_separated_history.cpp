// The energy SVD of a separated displacement history from its small factors
// (pgd/separated_history.hpp) against the eigen-decomposition of the n × m history's Gram matrix.
#include <gtest/gtest.h>

#include "fixtures/seed_scene.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/linalg/dense_decompositions.hpp"
#include "stcontact/pgd/controlled_global_stage.hpp"
#include "stcontact/pgd/separated_history.hpp"

TEST(SeparatedHistory, EnergySvdEqualsTheSvdOfTheFullHistory) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(31, 41));
  const stc::SolveResult reference = stc::solveIncremental(problem);
  stc::pgd::ControlledGlobalStage stage(problem, {});
  stc::InterfaceHistory hat, s;
  stc::latin::localStage(problem.contact, reference.interface, hat);
  stage.observeGap(0.0);
  stage.solve(hat, s);
  const auto& basis = stage.basis();
  const Eigen::MatrixXd u = basis.loadResponses() * basis.loadHistories() + basis.responses().times(stage.coordinates());
  // Dense: σ_i² are the eigenvalues of uᵀ A u (m × m).
  const Eigen::MatrixXd gram = u.transpose() * (stage.matrix() * u);
  const stc::linalg::SymmetricEigen dense = stc::linalg::symmetricEigen(0.5 * (gram + gram.transpose()));
  const Eigen::VectorXd sigma_dense = dense.values.reverse().cwiseMax(0.0).cwiseSqrt();
  const int r = 8;
  const stc::pgd::EnergySvd svd = stc::pgd::energySvd(basis, stage.coordinates(), r);
  ASSERT_EQ(svd.singular_values.size(), r);
  for (int i = 0; i < r; ++i) EXPECT_NEAR(svd.singular_values[i], sigma_dense[i], 1e-8 * sigma_dense[0]) << i;
  // The modes are A-orthonormal, their traces are B Y, and they carry the time functions.
  const Eigen::MatrixXd Y = stc::pgd::spatialModes(basis, svd.combination);
  EXPECT_LE((Y.transpose() * (stage.matrix() * Y) - Eigen::MatrixXd::Identity(r, r)).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LE((stc::pgd::modeTraces(basis, svd.combination) - problem.contact.B * Y).norm(), 1e-10 * Y.norm());
  const Eigen::MatrixXd rest = u - Y * svd.time_functions;
  const double tail = std::sqrt((sigma_dense.tail(sigma_dense.size() - r).squaredNorm()));
  EXPECT_NEAR(std::sqrt((rest.transpose() * (stage.matrix() * rest)).trace()), tail, 1e-6 * sigma_dense[0]);
}
