// The energy factor (pgd/energy_factor.hpp) built column by column against a Cholesky factorisation
// of the whole Gram matrix, with a dependent column, its projections of other vectors; and the randomized leading singular vectors of
// pgd/separated_history.hpp against Eigen's SVD.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "stcontact/pgd/energy_factor.hpp"
#include "stcontact/pgd/separated_history.hpp"

namespace {

// Appends the columns of Φ one by one given the SPD "energy" matrix A: products Φᵀ A φ_j.
stc::pgd::EnergyFactor factorOf(const Eigen::MatrixXd& Phi, const Eigen::MatrixXd& A) {
  stc::pgd::EnergyFactor factor;
  const Eigen::MatrixXd M = Phi.transpose() * A * Phi;
  for (Eigen::Index j = 0; j < Phi.cols(); ++j) factor.append(M.col(j).head(j + 1));
  return factor;
}

Eigen::MatrixXd spd(int n) {
  std::srand(3);
  const Eigen::MatrixXd R = Eigen::MatrixXd::Random(n, n);
  return R * R.transpose() + n * Eigen::MatrixXd::Identity(n, n);
}

}  // namespace

TEST(EnergyFactor, ColumnByColumnEqualsTheCholeskyFactorOfTheGramMatrix) {
  const Eigen::MatrixXd A = spd(30), Phi = Eigen::MatrixXd::Random(30, 12);
  const stc::pgd::EnergyFactor factor = factorOf(Phi, A);
  ASSERT_EQ(factor.rank(), 12);
  const Eigen::MatrixXd M = Phi.transpose() * A * Phi;
  const Eigen::MatrixXd R = M.llt().matrixU();
  EXPECT_LE((Eigen::MatrixXd(factor.coordinatesOfColumns()) - R).norm(), 1e-12 * R.norm());
  // The whitened modes Φ C with C = combination(I) are A-orthonormal, and Φ = (Φ C) R.
  const Eigen::MatrixXd Y = Phi * factor.combination(Eigen::MatrixXd::Identity(12, 12));
  EXPECT_LE((Y.transpose() * A * Y - Eigen::MatrixXd::Identity(12, 12)).cwiseAbs().maxCoeff(), 1e-10);
  const Eigen::MatrixXd theta = Eigen::MatrixXd::Random(12, 7);
  EXPECT_LE((Y * factor.whiten(theta) - Phi * theta).norm(), 1e-10 * (Phi * theta).norm());
}

TEST(EnergyFactor, ADependentColumnGetsNoRowButKeepsItsCoordinates) {
  const Eigen::MatrixXd A = spd(20);
  Eigen::MatrixXd Phi = Eigen::MatrixXd::Random(20, 5);
  Phi.col(3) = 2.0 * Phi.col(0) - Phi.col(2);  // in the span of the earlier columns
  const stc::pgd::EnergyFactor factor = factorOf(Phi, A);
  EXPECT_EQ(factor.size(), 5);
  EXPECT_EQ(factor.rank(), 4);
  const Eigen::MatrixXd Y = Phi * factor.combination(Eigen::MatrixXd::Identity(4, 4));
  EXPECT_LE((Y.transpose() * A * Y - Eigen::MatrixXd::Identity(4, 4)).cwiseAbs().maxCoeff(), 1e-10);
  const Eigen::MatrixXd theta = Eigen::MatrixXd::Random(5, 3);  // uses the dependent column too
  EXPECT_LE((Y * factor.whiten(theta) - Phi * theta).norm(), 1e-10 * (Phi * theta).norm());
}

// Blocks of columns (after 5 single ones, then 9 and 6 at once) give the factor of the same columns
// appended one by one; a block with a dependent column falls back to append's rules (no row).
TEST(EnergyFactor, ABlockOfColumnsIsTheirAppendOneByOne) {
  const Eigen::MatrixXd A = spd(40);
  for (const bool dependent : {false, true}) {
    Eigen::MatrixXd Phi = Eigen::MatrixXd::Random(40, 20);
    if (dependent) Phi.col(17) = Phi.col(2) - 3.0 * Phi.col(12);
    const Eigen::MatrixXd M = Phi.transpose() * A * Phi;
    stc::pgd::EnergyFactor blocks;
    for (int j = 0; j < 5; ++j) blocks.append(M.col(j).head(j + 1));
    blocks.appendBlock(M.block(0, 5, 14, 9));
    blocks.appendBlock(M.block(0, 14, 20, 6));
    const stc::pgd::EnergyFactor single = factorOf(Phi, A);
    ASSERT_EQ(blocks.size(), 20);
    ASSERT_EQ(blocks.rank(), dependent ? 19 : 20);
    ASSERT_EQ(single.rank(), blocks.rank());
    const Eigen::MatrixXd R = single.coordinatesOfColumns();
    EXPECT_LE((Eigen::MatrixXd(blocks.coordinatesOfColumns()) - R).norm(), 1e-12 * R.norm()) << dependent;
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(blocks.rank(), blocks.rank());
    EXPECT_LE((blocks.combination(I) - single.combination(I)).norm(), 1e-10 * single.combination(I).norm());
  }
}

TEST(EnergyFactor, ProjectionsAreTheCoordinatesOfTheEnergyProjectionOnTheSpan) {
  const Eigen::MatrixXd A = spd(20);
  Eigen::MatrixXd Phi = Eigen::MatrixXd::Random(20, 6);
  Phi.col(4) = Phi.col(1) + 0.5 * Phi.col(3);  // a dependent column: no row of its own
  const stc::pgd::EnergyFactor factor = factorOf(Phi, A);
  ASSERT_EQ(factor.rank(), 5);
  const Eigen::MatrixXd Phi_hat = Phi * factor.combination(Eigen::MatrixXd::Identity(5, 5));
  const Eigen::MatrixXd Y = Eigen::MatrixXd::Random(20, 3);
  const Eigen::MatrixXd S = factor.projections(Phi.transpose() * A * Y);
  EXPECT_LE((S - Phi_hat.transpose() * A * Y).norm(), 1e-10 * S.norm());
  // Y − Φ̂ S is A-orthogonal to span Φ: S holds the coordinates of Y's projection.
  EXPECT_LE((Phi.transpose() * A * (Y - Phi_hat * S)).norm(), 1e-9 * (Phi.transpose() * A * Y).norm());
}

TEST(LeadingSingularVectors, RandomizedEqualTheSvdsForADecayingSpectrum) {
  // 120 × 201 with singular values 0.6^i: the range finder with 2 subspace iterations and 10 extra
  // samples gets the leading 15 to round-off (HMT 2011, Theorem 10.8: error ~ σ_{k+p+1} (σ/σ)^{2q}).
  std::srand(5);
  const Eigen::MatrixXd U = Eigen::MatrixXd::Random(120, 120).householderQr().householderQ();
  const Eigen::MatrixXd V = Eigen::MatrixXd::Random(201, 120).householderQr().householderQ() *
                            Eigen::MatrixXd::Identity(201, 120);
  Eigen::VectorXd sigma(120);
  for (int i = 0; i < 120; ++i) sigma[i] = std::pow(0.6, i);
  const Eigen::MatrixXd C = U * sigma.asDiagonal() * V.transpose();
  const Eigen::MatrixXd leading = stc::pgd::leadingSingularVectors(C, 15);
  ASSERT_EQ(leading.cols(), 15);
  for (int i = 0; i < 15; ++i) EXPECT_NEAR(std::abs(leading.col(i).dot(U.col(i))), 1.0, 1e-8) << i;
  // Fewer when the rank is smaller: a rank-3 matrix gives 3.
  const Eigen::MatrixXd low = U.leftCols(3) * V.leftCols(3).transpose();
  EXPECT_EQ(stc::pgd::leadingSingularVectors(low, 15).cols(), 3);
}
