// The ARPACK wrapper (pgd/arpack_eigen.hpp): agreement with Eigen's dense symmetric eigensolver at
// both ends of the spectrum, orthonormal Ritz vectors, reproducibility, option checks, and ARPACK's
// error codes turned into exceptions that carry their meaning.
#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/linalg/dense_decompositions.hpp"
#include "stcontact/pgd/arpack_eigen.hpp"

namespace {

using stc::pgd::ArpackEigen;
using stc::pgd::ArpackOptions;
using stc::pgd::ArpackWhich;

// A random symmetric matrix with eigenvalues spread over [1, 100] (fixed seed).
Eigen::MatrixXd randomSymmetric(int n, unsigned seed) {
  std::mt19937 engine(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd G(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) G(i, j) = normal(engine);
  const Eigen::MatrixXd Q = stc::linalg::orthonormalColumns(G);
  Eigen::VectorXd d(n);
  for (int i = 0; i < n; ++i) d[i] = 1.0 + 99.0 * std::pow(static_cast<double>(i) / (n - 1), 2.0);
  return Q * d.asDiagonal() * Q.transpose();
}

ArpackEigen::Operator dense(const Eigen::MatrixXd& A) {
  return [&A](const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) { y.noalias() = A * x; };
}

TEST(ArpackEigen, LargestAlgebraicMatchesEigenDense) {
  const Eigen::MatrixXd A = randomSymmetric(120, 1);
  const stc::linalg::SymmetricEigen reference = stc::linalg::symmetricEigen(A);
  ArpackOptions options;
  options.eigenvalues = 8;
  ArpackEigen solver(120, options);
  const auto result = solver.compute(dense(A));
  ASSERT_EQ(result.values.size(), 8);
  for (int j = 0; j < 8; ++j) {
    const double expected = reference.values[119 - j];
    EXPECT_NEAR(result.values[j], expected, 1e-12 * expected) << "eigenvalue " << j;
    // Residual of the eigenpair, relative to ‖A‖ = 100.
    EXPECT_LT((A * result.vectors.col(j) - result.values[j] * result.vectors.col(j)).norm(), 1e-12 * 100.0);
  }
  EXPECT_GT(result.operator_applications, 0);
}

TEST(ArpackEigen, SmallestAlgebraicMatchesEigenDense) {
  const Eigen::MatrixXd A = randomSymmetric(80, 2);
  const stc::linalg::SymmetricEigen reference = stc::linalg::symmetricEigen(A);
  ArpackOptions options;
  options.eigenvalues = 4;
  options.which = ArpackWhich::SmallestAlgebraic;
  options.subspace = 30;  // the low end of this spectrum is clustered: a wider subspace
  const auto result = ArpackEigen(80, options).compute(dense(A));
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(result.values[j], reference.values[j], 1e-11) << j;
  EXPECT_LT(result.values[0], result.values[3]);  // ascending from the wanted end
}

TEST(ArpackEigen, RitzVectorsAreOrthonormal) {
  const Eigen::MatrixXd A = randomSymmetric(60, 3);
  ArpackOptions options;
  options.eigenvalues = 10;
  const auto result = ArpackEigen(60, options).compute(dense(A));
  const Eigen::MatrixXd gram = result.vectors.transpose() * result.vectors;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(10, 10)).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(ArpackEigen, DiagonalOperatorGivesItsLargestEntriesAndUnitVectors) {
  const int n = 50;
  Eigen::VectorXd d = Eigen::VectorXd::LinSpaced(n, 1.0, static_cast<double>(n));
  ArpackOptions options;
  options.eigenvalues = 3;
  const auto result = ArpackEigen(n, options).compute(
      [&](const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) { y = d.cwiseProduct(x); });
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(result.values[j], n - j, 1e-12 * n);
    EXPECT_NEAR(std::abs(result.vectors(n - 1 - j, j)), 1.0, 1e-12);
  }
}

TEST(ArpackEigen, RunsAreReproducible) {
  const Eigen::MatrixXd A = randomSymmetric(70, 4);
  ArpackOptions options;
  options.eigenvalues = 5;
  const auto a = ArpackEigen(70, options).compute(dense(A));
  const auto b = ArpackEigen(70, options).compute(dense(A));
  EXPECT_EQ(a.values, b.values);
  EXPECT_EQ(a.vectors, b.vectors);
  EXPECT_EQ(a.operator_applications, b.operator_applications);
}

TEST(ArpackEigen, InvalidOptionsNameTheFieldAndTheRule) {
  ArpackOptions options;
  options.eigenvalues = 10;
  try {
    ArpackEigen(10, options);
    FAIL() << "no exception";
  } catch (const stc::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("eigenvalues = 10"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("[1, n - 1]"), std::string::npos) << e.what();
  }
  options.eigenvalues = 3;
  options.subspace = 3;
  EXPECT_THROW(ArpackEigen(10, options), stc::InputError);
  options.subspace = 0;
  options.tolerance = -1.0;
  EXPECT_THROW(ArpackEigen(10, options), stc::InputError);
  options.tolerance = 0.0;
  options.max_restarts = 0;
  EXPECT_THROW(ArpackEigen(10, options), stc::InputError);
}

TEST(ArpackEigen, MaximumIterationsIsAnErrorCarryingArpacksMeaning) {
  // Eigenvalues 1 + 1e-6 i: a tight cluster that one restart of a 5-vector subspace cannot resolve.
  const int n = 300;
  const Eigen::VectorXd d = Eigen::VectorXd::LinSpaced(n, 1.0, 1.0 + 1e-6 * (n - 1));
  ArpackOptions options;
  options.eigenvalues = 2;
  options.subspace = 5;
  options.max_restarts = 1;
  ArpackEigen solver(n, options);
  try {
    solver.compute(
        [&](const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) { y = d.cwiseProduct(x); });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("dsaupd returned INFO = 1"), std::string::npos) << what;
    EXPECT_NE(what.find("maximum number of iterations"), std::string::npos) << what;
  }
}

TEST(ArpackEigen, MessagesFollowArpacksDocumentation) {
  EXPECT_NE(std::string(stc::pgd::arpackMessage("dsaupd", -3)).find("NCV must be greater than NEV"),
            std::string::npos);
  EXPECT_NE(std::string(stc::pgd::arpackMessage("dsaupd", -12)).find("IPARAM(1)"), std::string::npos);
  EXPECT_NE(std::string(stc::pgd::arpackMessage("dseupd", -12)).find("'BE'"), std::string::npos);
  EXPECT_NE(std::string(stc::pgd::arpackMessage("dseupd", -14)).find("sufficient accuracy"), std::string::npos);
  EXPECT_NE(std::string(stc::pgd::arpackMessage("dsaupd", 42)).find("unknown"), std::string::npos);
}

}  // namespace
