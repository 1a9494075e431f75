// Anderson mixing (src/linalg/anderson.hpp) on linear fixed-point maps x ← M x + b, where it is
// a Krylov method (Walker & Ni 2011, §4): with depth ≥ n it solves an n-dimensional problem in
// n + 1 steps, and on a slow contraction it needs far fewer steps than the plain iteration.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "stcontact/core/threads.hpp"
#include "stcontact/linalg/anderson.hpp"

namespace {

// A symmetric contraction of size n with eigenvalues spread over [−0.3 ρ, ρ], and a right-hand side.
struct LinearMap {
  Eigen::MatrixXd M, b;
  LinearMap(int n, double rho) {
    std::srand(7);
    const Eigen::MatrixXd Q = Eigen::MatrixXd(Eigen::MatrixXd::Random(n, n).householderQr().householderQ());
    M = Q * Eigen::VectorXd::LinSpaced(n, -0.3 * rho, rho).asDiagonal() * Q.transpose();
    b = Eigen::MatrixXd::Random(n, 2);  // two columns: iterates are matrices (rows × instants)
  }
  Eigen::MatrixXd solution() const { return (Eigen::MatrixXd::Identity(M.rows(), M.rows()) - M).lu().solve(b); }
};

// Steps of x ← M x + b, mixed with `depth` (0: plain), until ‖x − x*‖ ≤ tol ‖x*‖.
int stepsToSolve(const LinearMap& map, int depth, double tol, const Eigen::VectorXd& weights) {
  const Eigen::MatrixXd exact = map.solution();
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(map.b.rows(), map.b.cols());
  stc::AndersonMixing mixing(depth > 0 ? depth : 1, weights);
  constexpr int kLimit = 100000;
  for (int step = 1; step <= kLimit; ++step) {
    const Eigen::MatrixXd image = map.M * x + map.b;
    if (depth > 0) mixing.next(x, image);
    else x = image;
    if ((x - exact).norm() <= tol * exact.norm()) return step;
  }
  return kLimit + 1;
}

}  // namespace

TEST(AndersonMixing, SolvesASmallLinearProblemInSizePlusOneSteps) {
  // Walker & Ni, Theorem 2.2: with depth ≥ n the iterates are GMRES's; GMRES is exact after n steps.
  const LinearMap map(6, 0.95);
  const int mixed = stepsToSolve(map, 6, 1e-8, Eigen::VectorXd::Ones(6));
  std::printf("[ measured ] steps: mixed %d\n", mixed);
  EXPECT_LE(mixed, 6 + 2);
  EXPECT_GT(stepsToSolve(map, 0, 1e-8, Eigen::VectorXd::Ones(6)), 300);  // 0.95^k ≤ 1e-8: k ≈ 360
}

TEST(AndersonMixing, ShallowDepthStillBeatsThePlainIterationOnASlowContraction) {
  const LinearMap map(200, 0.98);
  const Eigen::VectorXd weights = Eigen::VectorXd::LinSpaced(200, 0.5, 2.0);  // a weighted norm changes γ, not the limit
  const int plain = stepsToSolve(map, 0, 1e-6, weights), mixed = stepsToSolve(map, 3, 1e-6, weights);
  std::printf("[ measured ] steps: plain %d, depth 3 %d\n", plain, mixed);
  EXPECT_GT(plain, 600);      // 0.98^k ≤ 1e-6: k ≈ 684
  EXPECT_LT(mixed, plain / 5);
}

TEST(AndersonMixing, FirstCallIsThePlainStep) {
  stc::AndersonMixing mixing(2, Eigen::VectorXd::Ones(3));
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(3, 1);
  const Eigen::MatrixXd image = Eigen::MatrixXd::Constant(3, 1, 1.5);
  mixing.next(x, image);
  EXPECT_EQ(x, image);
}

TEST(AndersonMixing, RefusesBadSizes) {
  EXPECT_THROW(stc::AndersonMixing(0, Eigen::VectorXd::Ones(3)), std::invalid_argument);
  stc::AndersonMixing mixing(2, Eigen::VectorXd::Ones(3));
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(4, 1);
  EXPECT_THROW(mixing.next(x, Eigen::MatrixXd::Zero(4, 1)), std::invalid_argument);
}

TEST(AndersonMixing, RestartsWhenAMixedIterateHasALargerResidual) {
  // A map that changes under the iteration (its constant term alternates in sign, as a nonsmooth
  // law switching branches would): the differences mix two maps, a mixed iterate's residual grows,
  // and the mixing restarts from a plain step instead of extrapolating on.
  const LinearMap map(20, 0.5);
  const Eigen::MatrixXd kick = 5.0 * Eigen::MatrixXd::Ones(20, 2);
  stc::AndersonMixing mixing(3, Eigen::VectorXd::Ones(20));
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(20, 2);
  for (int step = 0; step < 12; ++step) mixing.next(x, map.M * x + map.b + (step % 2 ? kick : -kick));
  EXPECT_GT(mixing.restarts(), 0);
  // On one fixed contraction it never restarts.
  stc::AndersonMixing steady(3, Eigen::VectorXd::Ones(20));
  Eigen::MatrixXd y = Eigen::MatrixXd::Zero(20, 2);
  for (int step = 0; step < 12; ++step) steady.next(y, map.M * y + map.b);
  EXPECT_EQ(steady.restarts(), 0);
}

TEST(AndersonMixing, TakingTheImageAndSplittingTheColumnsChangeNoBit) {
  // nextTaking keeps the image's storage instead of a copy, and both passes split the columns over
  // the threads with sums taken per column: the iterates are bitwise those of next on one thread.
  const LinearMap map(40, 0.9);
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(40, 37);  // more columns than threads
  const Eigen::VectorXd weights = Eigen::VectorXd::LinSpaced(40, 0.5, 2.0);
  const auto iterates = [&](int threads, bool taking) {
    const stc::ThreadCountScope scope(threads);
    stc::AndersonMixing mixing(3, weights);
    Eigen::MatrixXd x = Eigen::MatrixXd::Zero(40, 37), image;
    std::vector<Eigen::MatrixXd> out;
    for (int step = 0; step < 15; ++step) {
      image = map.M * x + b;
      if (taking) mixing.nextTaking(x, image);
      else mixing.next(x, image);
      out.push_back(x);
    }
    return out;
  };
  const std::vector<Eigen::MatrixXd> serial = iterates(1, false);
  for (const int threads : {1, 2, 3, 8})
    for (const bool taking : {false, true}) {
      const std::vector<Eigen::MatrixXd> run = iterates(threads, taking);
      for (size_t step = 0; step < serial.size(); ++step)
        ASSERT_TRUE(run[step] == serial[step]) << threads << " threads, taking " << taking << ", step " << step;
    }
  EXPECT_GT((serial.back() - serial.front()).norm(), 0.0);  // the iteration moved
}
