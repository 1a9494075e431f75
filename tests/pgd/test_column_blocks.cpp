// ColumnBlocks (pgd/column_blocks.hpp): columns kept in the blocks they were appended in give the
// products of the one matrix they make, for every leading count of columns (a block cut in two
// included), and refuse a block of other rows or more columns than they hold.
#include <gtest/gtest.h>

#include <Eigen/SparseCore>
#include <stdexcept>

#include "stcontact/pgd/column_blocks.hpp"

namespace {

// Blocks of 1, 3 and 2 columns of a 9-row matrix, and the matrix they make.
struct Blocks {
  Eigen::MatrixXd all = Eigen::MatrixXd::Random(9, 6);
  stc::pgd::ColumnBlocks blocks{9};
  Blocks() {
    blocks.append(Eigen::MatrixXd(all.leftCols(1)));
    blocks.append(Eigen::MatrixXd(all.middleCols(1, 3)));
    blocks.append(Eigen::MatrixXd(all.rightCols(2)));
  }
};

// Summed per block the product's rounding differs from one matrix's: agreement to a few ulps.
constexpr double kRoundoff = 1e-14;

TEST(ColumnBlocks, HoldsTheColumnsAppendedWithNothingSpare) {
  const Blocks b;
  EXPECT_EQ(b.blocks.cols(), 6);
  EXPECT_EQ(b.blocks.bytes(), 9.0 * 6.0 * sizeof(double));
  EXPECT_TRUE(b.blocks.gathered() == b.all);
}

TEST(ColumnBlocks, ProductsAreThoseOfTheOneMatrixForEveryLeadingCount) {
  const Blocks b;
  Eigen::SparseMatrix<double> S(2, 9);
  S.insert(0, 2) = 1.5;
  S.insert(1, 7) = -2.0;
  S.insert(1, 0) = 0.5;
  for (Eigen::Index p = 0; p <= 6; ++p) {  // p = 2, 3: the second block cut
    const Eigen::MatrixXd M = Eigen::MatrixXd::Random(p, 4);
    const Eigen::MatrixXd XM = b.all.leftCols(p) * M;
    EXPECT_LE((b.blocks.times(M) - XM).norm(), kRoundoff * (1.0 + XM.norm())) << p;
    Eigen::MatrixXd into = Eigen::MatrixXd::Ones(9, 4);
    b.blocks.addProduct(M, into);
    EXPECT_LE((into - XM - Eigen::MatrixXd::Ones(9, 4)).norm(), kRoundoff * (1.0 + into.norm())) << p;
    EXPECT_TRUE(b.blocks.rowsOf(S, p) == Eigen::MatrixXd(S * b.all.leftCols(p))) << p;
  }
}

TEST(ColumnBlocks, RefusesOtherRowsAndColumnsItDoesNotHold) {
  Blocks b;
  EXPECT_THROW(b.blocks.append(Eigen::MatrixXd::Zero(8, 1)), std::invalid_argument);
  EXPECT_THROW(b.blocks.times(Eigen::MatrixXd::Zero(7, 1)), std::out_of_range);
  EXPECT_EQ(b.blocks.cols(), 6);
}

}  // namespace
