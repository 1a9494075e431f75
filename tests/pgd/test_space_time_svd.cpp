// The a posteriori space-time SVD (pgd/space_time_svd.hpp, docs/method.md §3): orthonormality of the
// pairs in their products, the energy identity Σσ² = ‖U‖²_K, exact recovery of a known rank,
// ARPACK against the dense eigensolver (on random histories and on the seed scene, the check
// of docs/svd_seed.md), the Euclidean SVD as the K = I case, and option checks.
#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "fixtures/seed_scene.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/linalg/backends/cholmod_factor.hpp"
#include "stcontact/operators/displacement.hpp"
#include "stcontact/pgd/space_time_svd.hpp"

namespace {

using stc::pgd::EnergySvdOptions;
using stc::pgd::SpaceTimeSvd;
using stc::pgd::SvdMethod;

Eigen::MatrixXd randomMatrix(Eigen::Index rows, Eigen::Index cols, unsigned seed) {
  std::mt19937 engine(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd M(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < rows; ++i) M(i, j) = normal(engine);
  return M;
}

// The full stiffness of a small seed mesh (positive semi-definite: three rigid motions).
const stc::Problem& smallProblem() {
  static const stc::Problem problem = stc::buildProblem(stc::test::seedScene(21, 41));
  return problem;
}

// A history with a decaying spectrum: Σ_j 0.7^j a_j b_jᵀ over all m instants (σ_12/σ_1 ≈ 1e-2, well above
// the Gram route's resolution, so that orthonormality holds to 1e-10 on every mode tested).
Eigen::MatrixXd decayingHistory(int n, int m, unsigned seed) {
  const Eigen::MatrixXd A = randomMatrix(n, m, seed), B = randomMatrix(m, m, seed + 1);
  Eigen::VectorXd w(m);
  for (int j = 0; j < m; ++j) w[j] = std::pow(0.7, j);
  return A * w.asDiagonal() * B.transpose();
}

EnergySvdOptions arpack(int modes) {
  EnergySvdOptions o;
  o.method = SvdMethod::Arpack;
  o.modes = modes;
  return o;
}

double maxOffIdentity(const Eigen::MatrixXd& gram) {
  return (gram - Eigen::MatrixXd::Identity(gram.rows(), gram.cols())).cwiseAbs().maxCoeff();
}

TEST(EnergySvd, SquaredSingularValuesSumToTheSpaceTimeEnergy) {
  const auto& K = smallProblem().stiffness;
  const Eigen::MatrixXd U = decayingHistory(K.rows(), 30, 10);
  const SpaceTimeSvd s = stc::pgd::energySvd(U, K);
  const double energy = stc::pgd::squaredEnergyNorm(U, K);
  EXPECT_NEAR(s.sigma.squaredNorm(), energy, 1e-12 * energy);
  EXPECT_NEAR(s.total_energy, energy, 1e-14 * energy);
  EXPECT_NEAR(s.cumulativeEnergy(s.size() - 1), 1.0, 1e-12);
  for (int i = 1; i < s.size(); ++i) EXPECT_LE(s.sigma[i], s.sigma[i - 1]);
}

TEST(EnergySvd, ModesAreOrthonormalInTheEnergyProductAndTimeFunctionsInTheEuclideanOne) {
  const auto& K = smallProblem().stiffness;
  const Eigen::MatrixXd U = decayingHistory(K.rows(), 30, 20);
  for (const EnergySvdOptions& options : {EnergySvdOptions{SvdMethod::Dense, 12}, arpack(12)}) {
    const SpaceTimeSvd s = stc::pgd::energySvd(U, K, options);
    ASSERT_EQ(s.resolved, 12);
    EXPECT_LT(maxOffIdentity(s.space.transpose() * (K * s.space)), 1e-10);
    EXPECT_LT(maxOffIdentity(s.time.transpose() * s.time), 1e-13);
  }
}

TEST(EnergySvd, ArpackLeadingModesMatchTheDenseEigensolver) {
  const auto& K = smallProblem().stiffness;
  const Eigen::MatrixXd U = decayingHistory(K.rows(), 40, 30);
  const SpaceTimeSvd dense = stc::pgd::energySvd(U, K);
  const SpaceTimeSvd truncated = stc::pgd::energySvd(U, K, arpack(10));
  ASSERT_EQ(truncated.size(), 10);
  for (int i = 0; i < 10; ++i) {
    EXPECT_NEAR(truncated.sigma[i], dense.sigma[i], 1e-10 * dense.sigma[i]) << "sigma " << i;
    // Same sign convention, so the pairs themselves agree.
    EXPECT_LT((truncated.time.col(i) - dense.time.col(i)).norm(), 1e-8) << "time function " << i;
  }
  EXPECT_GT(truncated.operator_applications, 0);
  EXPECT_EQ(truncated.total_energy, dense.total_energy);
}

TEST(EnergySvd, RecoversAMatrixOfKnownRankExactly) {
  const auto& K = smallProblem().stiffness;
  const int n = static_cast<int>(K.rows()), m = 35, r = 4;
  const Eigen::MatrixXd U = randomMatrix(n, r, 40) * randomMatrix(m, r, 41).transpose();
  for (const EnergySvdOptions& options : {EnergySvdOptions{}, arpack(10)}) {
    const SpaceTimeSvd s = stc::pgd::energySvd(U, K, options);
    EXPECT_EQ(s.resolved, r);
    // The Gram route resolves σ down to σ_1 √(m ε) only (header, "Resolution"): σ_{r+1}/σ_1 is at
    // that floor, and the energy it stands for, (σ_{r+1}/σ_1)², is at the round-off of the energy.
    for (int i = r; i < s.size(); ++i) {
      EXPECT_LT(s.sigma[i] / s.sigma[0], std::sqrt(m * 2.2e-16)) << i;
      EXPECT_LT(s.energyFraction(i), 1e-12) << i;
    }
    EXPECT_LT(1.0 - s.cumulativeEnergy(r - 1), 1e-12);
    ASSERT_EQ(s.modesFor(1.0 - 1e-12), r);
    const Eigen::MatrixXd E = U - s.reconstruct(r);
    EXPECT_LT(std::sqrt(stc::pgd::squaredEnergyNorm(E, K) / s.total_energy), 1e-12);
    EXPECT_LT(E.norm() / U.norm(), 1e-12);
  }
}

TEST(EnergySvd, IdentityProductGivesThePlainSvd) {
  const int n = 60, m = 25;
  const Eigen::MatrixXd U = decayingHistory(n, m, 50);
  Eigen::SparseMatrix<double> I(n, n);
  I.setIdentity();
  const SpaceTimeSvd energy = stc::pgd::energySvd(U, I, {SvdMethod::Dense, 8});
  const SpaceTimeSvd plain = stc::pgd::plainSvd(U, 8);
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(energy.sigma[i], plain.sigma[i], 1e-10 * plain.sigma[i]);
    EXPECT_LT((energy.space.col(i) - plain.space.col(i)).norm(), 1e-7) << i;
  }
  EXPECT_LT(maxOffIdentity(plain.space.transpose() * plain.space), 1e-13);
  EXPECT_LT((U - stc::pgd::plainSvd(U).reconstruct(m)).norm(), 1e-13 * U.norm());
}

TEST(EnergySvd, ZeroHistoryHasZeroSingularValues) {
  const auto& K = smallProblem().stiffness;
  const SpaceTimeSvd s = stc::pgd::energySvd(Eigen::MatrixXd::Zero(K.rows(), 5), K);
  EXPECT_EQ(s.sigma.size(), 5);
  EXPECT_EQ(s.sigma.norm(), 0.0);
  EXPECT_EQ(s.resolved, 0);
  EXPECT_FALSE(s.modesFor(0.5).has_value());
}

TEST(EnergySvd, InvalidOptionsAndSizesAreInputErrors) {
  const auto& K = smallProblem().stiffness;
  const Eigen::MatrixXd U = randomMatrix(K.rows(), 6, 60);
  EXPECT_THROW(stc::pgd::energySvd(U, K, arpack(6)), stc::InputError);  // ARPACK: modes < m
  EXPECT_THROW(stc::pgd::energySvd(U, K, arpack(0)), stc::InputError);
  EXPECT_THROW(stc::pgd::energySvd(U, K, {SvdMethod::Dense, 7}), stc::InputError);
  EXPECT_THROW(stc::pgd::energySvd(U.topRows(10), K), stc::InputError);
  EXPECT_THROW(stc::pgd::plainSvd(U, 7), stc::InputError);
}

// The check of docs/svd_seed.md: on the seed scene (docs/method.md §6, 1142 dofs, 201 instants) solved by the
// incremental solver, ARPACK and the dense eigensolver agree on the leading 10 singular values.
TEST(EnergySvd, SeedSceneArpackAgreesWithDenseOnTheLeadingTenSingularValues) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene());
  const stc::SolveResult solved = stc::solveIncremental(problem);
  ASSERT_TRUE(solved.summary.converged()) << solved.summary.message;
  const stc::CholmodFactor factor(problem.stiffness_free, "K_ff");
  const Eigen::MatrixXd U = stc::fullDisplacements(problem, factor, solved.interface.lambda);
  ASSERT_EQ(U.rows(), 1142);
  ASSERT_EQ(U.cols(), 201);
  const SpaceTimeSvd dense = stc::pgd::energySvd(U, problem.stiffness);
  const SpaceTimeSvd truncated = stc::pgd::energySvd(U, problem.stiffness, arpack(10));
  double worst = 0.0;
  for (int i = 0; i < 10; ++i) {
    const double difference = std::abs(truncated.sigma[i] - dense.sigma[i]) / dense.sigma[i];
    worst = std::max(worst, difference);
    EXPECT_LE(difference, 1e-10) << "sigma " << i + 1;
  }
  const Eigen::MatrixXd Y = truncated.space.leftCols(10), V = truncated.time.leftCols(10);
  const double space_orthonormality = maxOffIdentity(Y.transpose() * (problem.stiffness * Y));
  const double time_orthonormality = maxOffIdentity(V.transpose() * V);
  std::cout << "[ seed     ] max relative difference ARPACK vs dense, leading 10 sigma: " << worst
            << "; sigma_10/sigma_1 = " << dense.sigma[9] / dense.sigma[0] << "; modes for 99.9 %: "
            << dense.modesFor(0.999).value_or(-1) << "; max |Y'KY - I| = " << space_orthonormality
            << ", max |V'V - I| = " << time_orthonormality << " (10 modes)\n";
  EXPECT_LT(space_orthonormality, 1e-10);
  EXPECT_LT(time_orthonormality, 1e-13);
}

}  // namespace
