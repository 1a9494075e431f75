// The dense decompositions (src/linalg/dense_decompositions.hpp): each one reconstructs its matrix
// to round-off, both SVD methods agree, the randomized range finder recovers the range of a matrix
// of exact low rank, and the Gaussian sketch is repeatable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "stcontact/linalg/dense_decompositions.hpp"

namespace {

using namespace stc::linalg;

// A 40 × 25 matrix of exact rank 6 with singular values 1, 1/3, ..., 1/3^5 (a spread of 243).
Eigen::MatrixXd lowRank() {
  const Eigen::MatrixXd U = orthonormalColumns(gaussianSketch(40, 6, 1));
  const Eigen::MatrixXd V = orthonormalColumns(gaussianSketch(25, 6, 2));
  Eigen::VectorXd s(6);
  for (int i = 0; i < 6; ++i) s[i] = std::pow(3.0, -i);
  return U * s.asDiagonal() * V.transpose();
}

TEST(DenseDecompositions, OrthonormalColumnsSpanTheLeadingColumns) {
  const Eigen::MatrixXd Y = gaussianSketch(30, 5, 3);
  const Eigen::MatrixXd Q = orthonormalColumns(Y);
  ASSERT_EQ(Q.rows(), 30);
  ASSERT_EQ(Q.cols(), 5);
  EXPECT_LT((Q.transpose() * Q - Eigen::MatrixXd::Identity(5, 5)).cwiseAbs().maxCoeff(), 1e-14);
  // Column 1 of Y lies in the span of Q's first two columns (QR: Y = Q R, R upper triangular).
  const Eigen::VectorXd y = Y.col(1);
  const Eigen::MatrixXd Q2 = Q.leftCols(2);
  EXPECT_LT((y - Q2 * (Q2.transpose() * y)).norm(), 1e-14 * y.norm());
}

// The range finder's shapes (hundreds of rows, tens of columns): wider than LAPACK's block of 32
// columns, so dgeqrf and dorgqr take their blocked paths; a dependent column must not break the
// orthonormality, and the nested spans still hold.
TEST(DenseDecompositions, OrthonormalColumnsOfAWideBlockWithADependentColumn) {
  Eigen::MatrixXd Y = gaussianSketch(600, 80, 7);
  Y.col(40) = Y.col(3) + Y.col(7);
  const Eigen::MatrixXd Q = orthonormalColumns(Y);
  ASSERT_EQ(Q.rows(), 600);
  ASSERT_EQ(Q.cols(), 80);
  EXPECT_LT((Q.transpose() * Q - Eigen::MatrixXd::Identity(80, 80)).cwiseAbs().maxCoeff(), 1e-13);
  for (const int j : {0, 31, 32, 40, 79}) {
    const Eigen::VectorXd y = Y.col(j);
    const Eigen::MatrixXd Qj = Q.leftCols(j + 1);
    EXPECT_LT((y - Qj * (Qj.transpose() * y)).norm(), 1e-13 * y.norm()) << "column " << j;
  }
}

// The complement of an orthonormal block: orthonormal, orthogonal to the block, and with it a square
// orthogonal matrix; on a small block and on one wider than LAPACK's blocks of 32 (dormqr's blocked
// path); an empty block gives the identity, a square one nothing.
TEST(DenseDecompositions, OrthonormalComplementCompletesAnOrthonormalBlock) {
  for (const auto& [n, p] : {std::pair{30, 7}, std::pair{300, 110}}) {
    const Eigen::MatrixXd Q = orthonormalColumns(gaussianSketch(n, p, 9));
    const Eigen::MatrixXd C = orthonormalComplement(Q);
    ASSERT_EQ(C.rows(), n);
    ASSERT_EQ(C.cols(), n - p);
    EXPECT_LT((C.transpose() * C - Eigen::MatrixXd::Identity(n - p, n - p)).cwiseAbs().maxCoeff(), 1e-13) << n;
    EXPECT_LT((Q.transpose() * C).cwiseAbs().maxCoeff(), 1e-13) << n;
    Eigen::MatrixXd square(n, n);
    square << Q, C;
    EXPECT_LT((square * square.transpose() - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff(), 1e-13) << n;
  }
  EXPECT_EQ(orthonormalComplement(Eigen::MatrixXd(6, 0)), Eigen::MatrixXd::Identity(6, 6));
  EXPECT_EQ(orthonormalComplement(orthonormalColumns(gaussianSketch(6, 6, 4))).cols(), 0);
}

TEST(DenseDecompositions, SymmetricEigenReconstructsAscending) {
  const Eigen::MatrixXd G = gaussianSketch(12, 12, 4);
  const Eigen::MatrixXd M = G + G.transpose();
  const SymmetricEigen eig = symmetricEigen(M);
  ASSERT_TRUE(eig.converged);
  for (Eigen::Index i = 1; i < eig.values.size(); ++i) EXPECT_LE(eig.values[i - 1], eig.values[i]);
  const Eigen::MatrixXd back = eig.vectors * eig.values.asDiagonal() * eig.vectors.transpose();
  EXPECT_LT((back - M).cwiseAbs().maxCoeff(), 1e-13 * M.cwiseAbs().maxCoeff());
}

TEST(DenseDecompositions, OrthonormalInAnSpdProductDropsDependentColumns) {
  // M = tridiag(-1, 4, -1), SPD; V's fourth column is the sum of its first two.
  const int n = 20;
  Eigen::SparseMatrix<double> M(n, n);
  for (int i = 0; i < n; ++i) {
    M.insert(i, i) = 4.0;
    if (i > 0) M.insert(i, i - 1) = -1.0;
    if (i + 1 < n) M.insert(i, i + 1) = -1.0;
  }
  Eigen::MatrixXd V = gaussianSketch(n, 4, 6);
  V.col(3) = V.col(0) + V.col(1);
  const Eigen::MatrixXd Y = orthonormalIn(V, M);
  ASSERT_EQ(Y.cols(), 3);
  EXPECT_LT((Y.transpose() * (M * Y) - Eigen::MatrixXd::Identity(3, 3)).cwiseAbs().maxCoeff(), 1e-12);
  // Every column of V lies in span Y: V = Y (Yᵀ M V).
  EXPECT_LT((V - Y * (Y.transpose() * (M * V))).norm(), 1e-12 * V.norm());
  EXPECT_EQ(orthonormalIn(Eigen::MatrixXd(n, 0), M).cols(), 0);
}

TEST(DenseDecompositions, BothSvdMethodsReconstructAndAgree) {
  const Eigen::MatrixXd M = gaussianSketch(50, 30, 5);  // 30 columns: BDCSVD divides (Jacobi below 16)
  const Svd jacobi = singularValueDecomposition(M, SvdMethod::jacobi, kThinU | kThinV);
  const Svd bdc = singularValueDecomposition(M, SvdMethod::divide_and_conquer, kThinU | kThinV);
  for (const Svd* s : {&jacobi, &bdc}) {
    ASSERT_EQ(s->U.cols(), 30);
    ASSERT_EQ(s->V.cols(), 30);
    EXPECT_LT((s->U * s->values.asDiagonal() * s->V.transpose() - M).cwiseAbs().maxCoeff(), 1e-12);
  }
  EXPECT_LT((jacobi.values - bdc.values).cwiseAbs().maxCoeff(), 1e-12 * jacobi.values[0]);
  const Svd values_only = singularValueDecomposition(M, SvdMethod::jacobi, kValuesOnly);
  EXPECT_EQ(values_only.U.size(), 0);
  EXPECT_EQ(values_only.V.size(), 0);
  EXPECT_LT((values_only.values - jacobi.values).cwiseAbs().maxCoeff(), 1e-12 * jacobi.values[0]);
}

// QR iteration and LAPACK's divide and conquer run on the taller of M and Mᵀ: a tall and a wide
// matrix, each factor asked for alone and both, reconstruct M and agree with Jacobi's singular values.
class LapackSvd : public ::testing::TestWithParam<SvdMethod> {};

TEST_P(LapackSvd, TallAndWideMatricesAgreeWithJacobi) {
  for (const auto& [rows, cols] : {std::pair{60, 25}, std::pair{25, 201}, std::pair{40, 40}}) {
    const Eigen::MatrixXd M = gaussianSketch(rows, cols, 8);
    const Svd jacobi = singularValueDecomposition(M, SvdMethod::jacobi, kValuesOnly);
    const Svd both = singularValueDecomposition(M, GetParam(), kThinU | kThinV);
    const Eigen::Index k = std::min(rows, cols);
    ASSERT_EQ(both.values.size(), k);
    ASSERT_EQ(both.U.rows(), rows);
    ASSERT_EQ(both.U.cols(), k);
    ASSERT_EQ(both.V.rows(), cols);
    ASSERT_EQ(both.V.cols(), k);
    EXPECT_LT((both.U * both.values.asDiagonal() * both.V.transpose() - M).cwiseAbs().maxCoeff(), 1e-12) << rows;
    EXPECT_LT((both.values - jacobi.values).cwiseAbs().maxCoeff(), 1e-12 * jacobi.values[0]) << rows;
    // One factor alone, up to signs: (UᵀM)(UᵀM)ᵀ = Σ² and (MV)ᵀ(MV) = Σ².
    const Eigen::MatrixXd squares = both.values.cwiseAbs2().asDiagonal();
    const Svd left = singularValueDecomposition(M, GetParam(), kThinU);
    EXPECT_EQ(left.V.size(), 0);
    const Eigen::MatrixXd UtM = left.U.transpose() * M;
    EXPECT_LT((UtM * UtM.transpose() - squares).cwiseAbs().maxCoeff(), 1e-12 * squares(0, 0)) << rows;
    const Svd right = singularValueDecomposition(M, GetParam(), kThinV);
    EXPECT_EQ(right.U.size(), 0);
    const Eigen::MatrixXd MV = M * right.V;
    EXPECT_LT((MV.transpose() * MV - squares).cwiseAbs().maxCoeff(), 1e-12 * squares(0, 0)) << rows;
    const Svd values = singularValueDecomposition(M, GetParam(), kValuesOnly);
    EXPECT_EQ(values.U.size() + values.V.size(), 0);
    EXPECT_LT((values.values - jacobi.values).cwiseAbs().maxCoeff(), 1e-12 * jacobi.values[0]) << rows;
  }
}

INSTANTIATE_TEST_SUITE_P(DenseDecompositions, LapackSvd,
                         ::testing::Values(SvdMethod::qr_iteration, SvdMethod::lapack_divide_and_conquer),
                         [](const auto& info) {
                           return info.param == SvdMethod::qr_iteration ? "QrIteration" : "DivideAndConquer";
                         });

// A graded spectrum, as a converged history's (σ_j = 10^(−j/4)): the vectors of the leading values
// span the same space by divide and conquer as by Jacobi, to the gap that separates them.
TEST(DenseDecompositions, DivideAndConquerKeepsTheLeadingSubspaceOfAGradedSpectrum) {
  const int p = 48, m = 501;
  const Eigen::VectorXd sigma = Eigen::VectorXd::LinSpaced(p, 0.0, -(p - 1) / 4.0).unaryExpr([](double e) {
    return std::pow(10.0, e);
  });
  const Eigen::MatrixXd M = orthonormalColumns(gaussianSketch(p, p, 3)) * sigma.asDiagonal() *
                            orthonormalColumns(gaussianSketch(m, p, 4)).transpose();
  const Svd dc = singularValueDecomposition(M, SvdMethod::lapack_divide_and_conquer, kThinU);
  const Svd jacobi = singularValueDecomposition(M, SvdMethod::jacobi, kThinU);
  EXPECT_LT((dc.values - sigma).cwiseAbs().maxCoeff(), 1e-13);  // to ε σ_1, σ_1 = 1 (backward stable)
  for (int lead : {4, 12, 24}) {  // ‖P_dc − P_jacobi‖ ≤ ε σ_1 / gap, gap = σ_lead (1 − 10^(−1/4)) ≥ 1e-6
    const Eigen::MatrixXd U = dc.U.leftCols(lead), V = jacobi.U.leftCols(lead);
    EXPECT_LT((U * U.transpose() - V * V.transpose()).norm(), 1e-8) << lead;
  }
}

TEST(DenseDecompositions, RandomizedRangeHoldsAnExactlyLowRankRange) {
  const Eigen::MatrixXd R = lowRank();
  for (int power : {0, 2}) {
    const Eigen::MatrixXd Q = randomizedRange(R, 6, power, 7);
    ASSERT_EQ(Q.cols(), 6);
    EXPECT_LT((R - Q * (Q.transpose() * R)).norm(), 1e-12 * R.norm()) << "power iterations " << power;
  }
}

TEST(DenseDecompositions, GaussianSketchIsRepeatableAndStandard) {
  const Eigen::MatrixXd a = gaussianSketch(200, 50, 9), b = gaussianSketch(200, 50, 9);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, gaussianSketch(200, 50, 10));
  // 10 000 standard normal samples: mean within 4 standard errors (0.04) of 0, variance within 0.06 of 1.
  EXPECT_LT(std::abs(a.mean()), 0.04);
  EXPECT_LT(std::abs((a.array() - a.mean()).square().mean() - 1.0), 0.06);
}

}  // namespace
