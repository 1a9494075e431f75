// The dense products written without a zeroing pass (src/linalg/dense_product.hpp): the same as
// Eigen's product to round-off, whatever C held before, on blocks read with their stride.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "stcontact/core/threads.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/linalg/dense_decompositions.hpp"
#include "stcontact/linalg/dense_product.hpp"

namespace {

using namespace stc::linalg;

// (rows, inner, columns): below Eigen's coefficient-wise threshold, a short inner dimension, a long
// history, a square operator, a wide short result.
class DenseProductShapes : public ::testing::TestWithParam<std::tuple<int, int, int>> {};

TEST_P(DenseProductShapes, AgreesWithEigenWhateverTheResultHeld) {
  const auto [rows, inner, cols] = GetParam();
  const Eigen::MatrixXd A = gaussianSketch(rows, inner, 1), B = gaussianSketch(inner, cols, 2);
  const Eigen::MatrixXd expected = A * B;
  const double tolerance = 1e-13 * std::sqrt(static_cast<double>(inner));
  // C held NaNs and has the right shape already: β = 0 must not read them.
  Eigen::MatrixXd C = Eigen::MatrixXd::Constant(rows, cols, std::numeric_limits<double>::quiet_NaN());
  multiply(A, B, C);
  EXPECT_LE((C - expected).cwiseAbs().maxCoeff(), tolerance);
  Eigen::MatrixXd T = Eigen::MatrixXd::Constant(1, 1, std::numeric_limits<double>::quiet_NaN());
  multiplyTransposed(Eigen::MatrixXd(A.transpose()), B, T);
  ASSERT_EQ(T.rows(), rows);
  ASSERT_EQ(T.cols(), cols);
  EXPECT_LE((T - expected).cwiseAbs().maxCoeff(), tolerance);
  EXPECT_TRUE(freshProduct(A, B) == C);
}

INSTANTIATE_TEST_SUITE_P(Shapes, DenseProductShapes,
                         ::testing::Values(std::make_tuple(7, 3, 5), std::make_tuple(40, 3, 2001),
                                           std::make_tuple(591, 45, 2001), std::make_tuple(300, 300, 101),
                                           std::make_tuple(2, 600, 5000)));

// Where the BLAS takes concurrent calls, a large product is split into column ranges on the
// threads; each column must keep the bits of one dgemm on any thread count (the ranges start at
// multiples of 192 columns, none small enough for OpenBLAS's small-matrix kernels). With a serial
// BLAS nothing is split and the products are one dgemm on every count. Shapes: the exact stage of
// fas-apriori (the zone's operator by a history), a short inner dimension, a product just above the
// small-matrix bound, columns that are not a multiple of 192, a block read with its stride.
TEST(DenseProduct, SplitOverThreadsEveryColumnKeepsTheBitsOfOneProduct) {
  std::cout << "BLAS takes concurrent calls: " << blasTakesConcurrentCalls() << "\n";
  const Eigen::MatrixXd big = gaussianSketch(920, 4010, 9);  // holds every shape below from (3, 5)
  for (const auto& [rows, inner, cols] : {std::make_tuple(915, 915, 2001), std::make_tuple(591, 45, 4001),
                                          std::make_tuple(60, 90, 600), std::make_tuple(402, 60, 2000)}) {
    const Eigen::MatrixXd A = gaussianSketch(rows, inner, 1), At = A.transpose();
    const auto B = big.block(3, 5, inner, cols);
    const Eigen::MatrixXd start = gaussianSketch(rows, cols, 3);
    Eigen::MatrixXd one, one_t, one_add = start;
    {
      const stc::ThreadCountScope scope(1);
      multiply(A, B, one);
      multiplyTransposed(At, B, one_t);
      multiplyAdd(A, B, one_add);
    }
    for (int threads : {2, 3}) {
      const stc::ThreadCountScope scope(threads);
      Eigen::MatrixXd C, T, S = start;
      multiply(A, B, C);
      multiplyTransposed(At, B, T);
      multiplyAdd(A, B, S);
      EXPECT_TRUE(C == one) << rows << " x " << inner << " x " << cols << ", " << threads << " threads";
      EXPECT_TRUE(T == one_t) << rows << " x " << inner << " x " << cols << ", " << threads << " threads";
      EXPECT_TRUE(S == one_add) << rows << " x " << inner << " x " << cols << ", " << threads << " threads";
    }
    EXPECT_LE((one_add - start - one).cwiseAbs().maxCoeff(), 1e-12 * std::sqrt(static_cast<double>(inner)));
  }
}

TEST(DenseProduct, BlocksAreReadWithTheirStride) {
  const Eigen::MatrixXd A = gaussianSketch(50, 40, 4), big = gaussianSketch(60, 3000, 5);
  const auto B = big.block(10, 100, 40, 2500);  // an outer stride of 60, not 40
  Eigen::MatrixXd C;
  multiply(A, B, C);
  EXPECT_LE((C - A * B).cwiseAbs().maxCoeff(), 1e-12);
  const auto At = big.block(3, 7, 40, 50);  // Aᵀ from a block: 40 × 50, stride 60
  multiplyTransposed(At, B, C);
  EXPECT_LE((C - At.transpose() * B).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(DenseProduct, EmptyInnerDimensionGivesZerosAndEmptyResultsStayEmpty) {
  EXPECT_TRUE(freshProduct(Eigen::MatrixXd(4, 0), Eigen::MatrixXd(0, 6)) == Eigen::MatrixXd::Zero(4, 6));
  EXPECT_EQ(freshProduct(Eigen::MatrixXd(0, 3), Eigen::MatrixXd::Ones(3, 6)).size(), 0);
  EXPECT_EQ(freshProduct(Eigen::MatrixXd::Ones(4, 3), Eigen::MatrixXd(3, 0)).size(), 0);
}

TEST(DenseProduct, MismatchedShapesAreRefused) {
  EXPECT_THROW(freshProduct(Eigen::MatrixXd(4, 3), Eigen::MatrixXd(2, 6)), std::invalid_argument);
  Eigen::MatrixXd C;
  EXPECT_THROW(multiplyTransposed(Eigen::MatrixXd(4, 3), Eigen::MatrixXd(3, 6), C), std::invalid_argument);
  Eigen::MatrixXd wrong(4, 5);
  EXPECT_THROW(multiplyAdd(Eigen::MatrixXd(4, 3), Eigen::MatrixXd(3, 6), wrong), std::invalid_argument);
}

}  // namespace
