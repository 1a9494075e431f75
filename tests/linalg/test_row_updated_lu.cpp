// RowUpdatedLu (src/linalg/row_updated_lu.hpp): a sequence of systems that differ from the
// factorised one in a few rows is solved through the Woodbury formula to the accuracy of a new LU;
// a new key, too many changed rows or an update that leaves a large residual make a new LU.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <limits>
#include <stdexcept>
#include <vector>

#include "stcontact/linalg/row_updated_lu.hpp"

namespace {

using stc::linalg::RowUpdatedLu;

// A well-conditioned n × n matrix (random entries, diagonally dominant) from `seed`.
Eigen::MatrixXd wellConditioned(int n, unsigned seed) {
  std::srand(seed);
  Eigen::MatrixXd M = Eigen::MatrixXd::Random(n, n);
  M.diagonal().array() += 2.0 * n;
  return M;
}

// M with `rows` replaced by random rows that keep it diagonally dominant.
Eigen::MatrixXd withRowsChanged(Eigen::MatrixXd M, const std::vector<int>& rows, unsigned seed) {
  std::srand(seed);
  for (int i : rows) {
    M.row(i) = Eigen::RowVectorXd::Random(M.cols());
    M(i, i) += 2.0 * M.cols();
  }
  return M;
}

double relativeError(const Eigen::VectorXd& x, const Eigen::VectorXd& exact) {
  return (x - exact).norm() / exact.norm();
}

TEST(RowUpdatedLu, ChangedRowsAreSolvedByUpdatingTheFactorToTheAccuracyOfANewLu) {
  const int n = 60;
  const std::vector<int> key{1, 2, 3};
  const Eigen::MatrixXd M0 = wellConditioned(n, 3);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  RowUpdatedLu lu;
  EXPECT_LT(relativeError(lu.solve(key, M0, b), M0.partialPivLu().solve(b)), 1e-13);
  // Rows 4, 17, 40 changed, then 4 and 59 (18 of 60 rows at most): every system through the factor of M0.
  for (const std::vector<int>& rows : {std::vector<int>{4, 17, 40}, std::vector<int>{4, 59}, std::vector<int>{}}) {
    const Eigen::MatrixXd M = withRowsChanged(M0, rows, 11);
    const Eigen::VectorXd x = lu.solve(key, M, b);
    EXPECT_LT(relativeError(x, M.partialPivLu().solve(b)), 1e-12) << rows.size() << " rows changed";
    EXPECT_LT((b - M * x).norm(), RowUpdatedLu::kResidualBound * b.norm());
  }
  EXPECT_EQ(lu.counts().factorisations, 1);
  EXPECT_EQ(lu.counts().updates, 3);
  EXPECT_EQ(lu.counts().rejected, 0);
}

TEST(RowUpdatedLu, ANewKeyOrTooManyChangedRowsMakeANewFactorisation) {
  const int n = 40;
  const Eigen::MatrixXd M0 = wellConditioned(n, 5);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  RowUpdatedLu lu(0.25);  // at most 10 of 40 rows
  lu.solve({0}, M0, b);
  lu.solve({1}, M0, b);  // the same matrix under another key
  EXPECT_EQ(lu.counts().factorisations, 2);
  std::vector<int> eleven;
  for (int i = 0; i < 11; ++i) eleven.push_back(3 * i);
  const Eigen::MatrixXd M = withRowsChanged(M0, eleven, 13);
  EXPECT_LT(relativeError(lu.solve({1}, M, b), M.partialPivLu().solve(b)), 1e-13);
  EXPECT_EQ(lu.counts().factorisations, 3);
  EXPECT_EQ(lu.counts().updates, 0);
  // Ten rows changed from M: within the share, an update.
  const Eigen::MatrixXd M2 = withRowsChanged(M, std::vector<int>(eleven.begin(), eleven.begin() + 10), 17);
  EXPECT_LT(relativeError(lu.solve({1}, M2, b), M2.partialPivLu().solve(b)), 1e-12);
  EXPECT_EQ(lu.counts().updates, 1);
}

// A singular factorised matrix (two equal rows): its LU's pivots divide by zero, the update's
// answer is not finite, it is rejected and the system solved by a new LU of the regular matrix.
TEST(RowUpdatedLu, AnUpdateFromASingularFactorIsRejectedAndTheSystemFactorised) {
  const int n = 30;
  Eigen::MatrixXd singular = wellConditioned(n, 7);
  singular.row(5) = singular.row(6);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 3.0);
  RowUpdatedLu lu;
  lu.solve({0}, singular, b);
  const Eigen::MatrixXd regular = withRowsChanged(singular, {5}, 19);
  const Eigen::VectorXd x = lu.solve({0}, regular, b);
  EXPECT_LT(relativeError(x, regular.partialPivLu().solve(b)), 1e-13);
  EXPECT_EQ(lu.counts().rejected, 1);
  EXPECT_EQ(lu.counts().factorisations, 2);
}

TEST(RowUpdatedLu, ANonFiniteEntryCountsAsAChangedRow) {
  const int n = 20;
  const Eigen::MatrixXd M0 = wellConditioned(n, 9);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  RowUpdatedLu lu;
  lu.solve({0}, M0, b);
  Eigen::MatrixXd M = M0;
  M(3, 8) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(lu.solve({0}, M, b).allFinite());  // through a rejected update, then the LU of M
  EXPECT_EQ(lu.counts().rejected, 1);
}

// The Newton systems' way (cone_newton.cpp): each M differs from the previous one in the rows named,
// and a row may change back to M₀'s. Told which rows changed, the solver finds the same rows
// differing from M₀ as by comparing all of M, so the same x bit for bit, and the same counts.
TEST(RowUpdatedLu, RowsNamedAsChangedGiveTheSameSolutionsBitForBit) {
  const int n = 50;
  const Eigen::MatrixXd M0 = wellConditioned(n, 21);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -2.0, 1.0);
  RowUpdatedLu compared, told;
  EXPECT_EQ(compared.solve({7}, M0, b), told.solve({7}, M0, b, {}));
  Eigen::MatrixXd M = M0;
  // Rows 3 and 30 change; then 3 again and 44; then 30 goes back to M₀'s row; then nothing.
  const std::vector<std::vector<Eigen::Index>> steps{{3, 30}, {3, 44}, {30}, {}};
  unsigned seed = 23;
  for (const std::vector<Eigen::Index>& rows : steps) {
    for (Eigen::Index i : rows) {
      if (rows.size() == 1) M.row(i) = M0.row(i);  // back to M₀'s row
      else M.row(i) = withRowsChanged(M, {static_cast<int>(i)}, ++seed).row(i);
    }
    const Eigen::VectorXd x = told.solve({7}, M, b, rows);
    EXPECT_EQ(x, compared.solve({7}, M, b)) << rows.size() << " rows named";
    EXPECT_LT(relativeError(x, M.partialPivLu().solve(b)), 1e-12);
  }
  EXPECT_EQ(told.counts().factorisations, 1);
  EXPECT_EQ(told.counts().updates, compared.counts().updates);
  EXPECT_EQ(told.counts().updates, 4);
  // A row outside M is the caller's error.
  EXPECT_THROW(told.solve({7}, M, b, {n}), std::invalid_argument);
}

TEST(RowUpdatedLu, RejectsAShareOutsideZeroOneAndMismatchedSizes) {
  EXPECT_THROW(RowUpdatedLu(1.5), std::invalid_argument);
  EXPECT_THROW(RowUpdatedLu(-0.1), std::invalid_argument);
  RowUpdatedLu lu;
  EXPECT_THROW(lu.solve({0}, Eigen::MatrixXd::Identity(3, 4), Eigen::VectorXd::Ones(3)), std::invalid_argument);
  EXPECT_THROW(lu.solve({0}, Eigen::MatrixXd::Identity(3, 3), Eigen::VectorXd::Ones(4)), std::invalid_argument);
}

}  // namespace
