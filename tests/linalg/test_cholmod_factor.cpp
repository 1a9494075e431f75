// CholmodFactor (src/linalg/backends/cholmod_factor.hpp): solves A X = B to round-off, refuses what is not positive
// definite, and gives bitwise the same columns in any workspace, also with two threads solving at
// once with one factor (what the threaded global stage relies on, docs/threads.md).
#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>
#include <vector>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/core/threads.hpp"
#include "stcontact/linalg/backends/cholmod_factor.hpp"
#include "stcontact/problem/problem.hpp"

namespace {

const stc::Problem& problem() {
  static const stc::Problem p = stc::buildProblem(stc::test::seedScene(31, 41));
  return p;
}

// Random right-hand sides for K_ff, from a seed (the same every run).
Eigen::MatrixXd randomRightHandSides(unsigned seed, int columns) {
  std::srand(seed);
  return Eigen::MatrixXd::Random(problem().stiffness_free.rows(), columns);
}

}  // namespace

TEST(CholmodFactor, SolvesEveryColumnToRoundOff) {
  const auto& A = problem().stiffness_free;
  const stc::CholmodFactor factor(A, "K_ff");
  const Eigen::MatrixXd B = randomRightHandSides(5, 37);  // two chunks of 16 and a rest
  const Eigen::MatrixXd X = factor.solve(B);
  EXPECT_LE((A * X - B).norm(), 1e-10 * B.norm());
  // Alone, a column goes through CHOLMOD's one-column kernel instead of the four-column one: the
  // same solution to round-off, not bitwise (why CholmodFactor fixes its chunks of columns).
  const Eigen::VectorXd x = factor.solve(Eigen::VectorXd(B.col(20)));
  EXPECT_LE((x - X.col(20)).norm(), 1e-13 * X.col(20).norm());
}

TEST(CholmodFactor, RefusesAMatrixWithRigidMotionsOrANegativePivot) {
  EXPECT_THROW(stc::CholmodFactor(problem().stiffness, "K"), stc::InputError);  // no Dirichlet condition
  Eigen::SparseMatrix<double> negative = problem().stiffness_free;
  negative.coeffRef(3, 3) = -1.0;
  EXPECT_THROW(stc::CholmodFactor(negative, "K"), stc::InputError);
}

TEST(CholmodFactor, SolvesBitwiseAlikeInAnyWorkspaceAndOnTwoThreadsAtOnce) {
  const stc::CholmodFactor factor(problem().stiffness_free, "K_ff");
  const Eigen::MatrixXd B = randomRightHandSides(6, 50);
  const Eigen::MatrixXd X = factor.solve(B);
  stc::CholmodFactor::Workspace w1, w2;
  EXPECT_TRUE(factor.solve(B, w1) == X);
  int wrong_left = 0, wrong_right = 0;  // two threads, two workspaces, one factor
  std::thread a([&] {
    for (int r = 0; r < 50; ++r) wrong_left += !(factor.solve(B.leftCols(32), w1) == X.leftCols(32));
  });
  std::thread b([&] {
    for (int r = 0; r < 50; ++r) wrong_right += !(factor.solve(B.rightCols(18), w2) == X.rightCols(18));
  });
  a.join();
  b.join();
  EXPECT_EQ(wrong_left, 0);
  EXPECT_EQ(wrong_right, 0);
}

TEST(CholmodFactor, SolvesOnThreadsBitwiseAsOnOne) {
  // solveOnThreads hands the chunks of solve(B) to the threads: the same columns whatever the count
  // (the incremental solver's Delassus operator relies on it: its reference is the same on any).
  const auto& A = problem().stiffness_free;
  const stc::CholmodFactor factor(A, "K_ff");
  const Eigen::MatrixXd B = randomRightHandSides(9, 83);  // five chunks of 16 and a rest
  const Eigen::MatrixXd serial = factor.solve(B);
  for (int threads : {1, 2, 3, 8}) {
    const stc::ThreadCountScope scope(threads);
    const Eigen::MatrixXd X = factor.solveOnThreads(B);
    EXPECT_EQ((X - serial).cwiseAbs().maxCoeff(), 0.0) << threads << " threads";
  }
  EXPECT_THROW(factor.solveOnThreads(Eigen::MatrixXd::Ones(A.rows() + 1, 40)), std::invalid_argument);
}

TEST(CholmodFactor, SolvesInPartsBitwiseOnAnyThreadCount) {
  // solveInParts: one CHOLMOD call per part of `part` columns, whichever thread takes it (the separated
  // stage's new directions in parts of 4: the same responses on any thread count).
  const auto& A = problem().stiffness_free;
  const stc::CholmodFactor factor(A, "K_ff");
  const Eigen::MatrixXd B = randomRightHandSides(10, 23);  // five parts of 4 and a rest of 3
  std::vector<stc::CholmodFactor::Workspace> serial_workspaces;
  Eigen::MatrixXd serial;
  {
    const stc::ThreadCountScope one(1);
    serial = factor.solveInParts(B, 4, serial_workspaces);
  }
  EXPECT_EQ(serial_workspaces.size(), 1u);
  std::vector<stc::CholmodFactor::Workspace> workspaces;
  for (int threads : {2, 3, 8}) {
    const stc::ThreadCountScope scope(threads);
    const Eigen::MatrixXd X = factor.solveInParts(B, 4, workspaces);  // workspaces kept between calls
    EXPECT_EQ((X - serial).cwiseAbs().maxCoeff(), 0.0) << threads << " threads";
  }
  EXPECT_EQ(workspaces.size(), 6u);  // grown to the largest count that had parts for it (6 parts)
  EXPECT_LE((A * serial - B).norm(), 1e-10 * B.norm());
  EXPECT_THROW(factor.solveInParts(B, 0, workspaces), std::invalid_argument);
  EXPECT_THROW(factor.solveInParts(B, stc::CholmodFactor::kChunk + 1, workspaces), std::invalid_argument);
}

// The half-ball's stiffness (3D, divisions 6: fl / lnz = 282 ≥ kSupernodalSolveSwitch) keeps its
// supernodal factor and solves through the BLAS; the seed's (2D) is simplicial. The same properties
// hold: round-off solutions, bitwise the same on any thread count and when two threads solve at once
// (with Debian's serial OpenBLAS, not safe for concurrent calls, they take turns; with its pthread
// build the chunks run on the threads at once).
TEST(CholmodFactor, ASupernodalFactorIn3dSolvesToRoundOffAndBitwiseOnAnyThreadCount) {
  EXPECT_FALSE(stc::CholmodFactor(problem().stiffness_free, "K_ff").isSupernodal());
  const stc::Problem ball = stc::buildProblem(stc::test::hemisphereScene(6, 3));
  const auto& A = ball.stiffness_free;
  const stc::CholmodFactor factor(A, "K_ff");
  ASSERT_TRUE(factor.isSupernodal());
  std::srand(11);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), 45);  // a chunk of 32 and a rest
  const Eigen::MatrixXd X = factor.solve(B);
  EXPECT_LE((A * X - B).norm(), 1e-10 * B.norm());
  for (int threads : {1, 2, 3}) {
    const stc::ThreadCountScope scope(threads);
    std::vector<stc::CholmodFactor::Workspace> workspaces;
    EXPECT_EQ((factor.solveOnThreads(B) - X).cwiseAbs().maxCoeff(), 0.0) << threads << " threads";
    EXPECT_EQ((factor.solveInParts(B, 4, workspaces) - X).cwiseAbs().maxCoeff(), 0.0) << threads << " threads";
  }
  stc::CholmodFactor::Workspace w1, w2;
  int wrong_left = 0, wrong_right = 0;
  std::thread a([&] {
    for (int r = 0; r < 10; ++r) wrong_left += !(factor.solve(B, w1) == X);
  });
  std::thread b([&] {
    for (int r = 0; r < 10; ++r) wrong_right += !(factor.solve(B, w2) == X);
  });
  a.join();
  b.join();
  EXPECT_EQ(wrong_left + wrong_right, 0);
}

namespace {

// C A⁻¹ Cᵀ by solves, as the Delassus operator was formed before the trailing block.
Eigen::MatrixXd bySolves(const stc::CholmodFactor& factor, const Eigen::SparseMatrix<double>& C) {
  return C * factor.solve(Eigen::MatrixXd(C.transpose()));
}

// The zone's B and its free dofs, for the seed (2D) and the half-ball (3D).
struct ZoneRows {
  Eigen::SparseMatrix<double> B;
  std::vector<int> dofs;
};
ZoneRows zoneRows(const stc::Problem& p, const std::vector<int>& zone) {
  ZoneRows z{stc::restrictToNodes(p.contact, zone).B, {}};
  z.dofs = stc::dofsReadBy(z.B);
  return z;
}

}  // namespace

// The trailing block of L is the Cholesky factor of the Schur complement on the trailing dofs, so
// condensed(C) = C A⁻¹ Cᵀ without a solve: the operator the solves give, to round-off, symmetric
// bitwise; the factor still solves A to round-off, and forces on the trailing dofs by a backward
// solve alone; a C reading other dofs is refused.
TEST(CholmodFactor, TheTrailingBlockGivesTheCondensedOperatorOfTheSolves) {
  const stc::Problem seed = stc::buildProblem(stc::test::seedScene(101, 11));
  const stc::Problem ball = stc::buildProblem(stc::test::hemisphereScene(6, 11));
  for (const stc::Problem* p : {&seed, &ball}) {
    std::vector<int> zone;
    for (int i = 0; i < p->contact.size(); i += 3) zone.push_back(i);
    const ZoneRows z = zoneRows(*p, zone);
    const stc::CholmodFactor plain(p->stiffness_free, "K_ff");
    const stc::CholmodFactor last(p->stiffness_free, "K_ff", z.dofs, 0.0);
    ASSERT_TRUE(last.condenses(z.B));
    EXPECT_FALSE(plain.condenses(z.B));
    EXPECT_FALSE(last.condenses(p->contact.B));  // the nodes left out read other dofs
    const Eigen::MatrixXd W = last.condensed(z.B), reference = bySolves(plain, z.B);
    EXPECT_LE((W - reference).norm(), 1e-12 * reference.norm());
    EXPECT_TRUE(W == W.transpose());
    EXPECT_THROW(last.condensed(p->contact.B), std::invalid_argument);
    EXPECT_THROW(plain.condensed(z.B), std::invalid_argument);
    const Eigen::MatrixXd rhs = Eigen::MatrixXd::Ones(p->stiffness_free.rows(), 3);
    EXPECT_LE((p->stiffness_free * last.solve(rhs) - rhs).norm(), 1e-10 * rhs.norm());
    // Forces on the trailing dofs: the forward solve on the dense block, the backward one sparse.
    std::srand(3);
    const Eigen::MatrixXd U = Eigen::MatrixXd::Random(z.B.rows(), 40);  // two supernodal chunks and more
    const Eigen::MatrixXd X = plain.solve(Eigen::MatrixXd(z.B.transpose() * U));
    const Eigen::MatrixXd from_trailing = last.solveFromTrailing(z.B, U);
    EXPECT_LE((from_trailing - X).norm(), 1e-11 * X.norm());
    for (int threads : {1, 3}) {  // the chunks on the threads: the bits of two
      const stc::ThreadCountScope scope(threads);
      EXPECT_TRUE(last.solveFromTrailing(z.B, U) == from_trailing) << threads << " threads";
    }
    EXPECT_THROW(last.solveFromTrailing(p->contact.B, Eigen::MatrixXd::Ones(p->contact.B.rows(), 1)),
                 std::invalid_argument);
  }
}

// Below the work bound the dofs are not moved: the plain factor, nothing condensed. Forced, on this
// small mesh CHOLMOD factorises simplicially: the block read from that form is the solves' too.
TEST(CholmodFactor, AFewTrailingDofsOnASmallFactorKeepThePlainOrdering) {
  const ZoneRows z = zoneRows(problem(), {0, 1, 2});
  EXPECT_FALSE(stc::CholmodFactor(problem().stiffness_free, "K_ff", z.dofs).condenses(z.B));
  const stc::CholmodFactor forced(problem().stiffness_free, "K_ff", z.dofs, 0.0);
  ASSERT_TRUE(forced.condenses(z.B));
  const Eigen::MatrixXd reference = bySolves(forced, z.B);
  EXPECT_LE((forced.condensed(z.B) - reference).norm(), 1e-12 * reference.norm());
  EXPECT_THROW(stc::CholmodFactor(problem().stiffness_free, "K_ff", {0, 0}, 0.0), std::invalid_argument);
  // Every dof last: a dense block of n³/3 flops, far above ten times the sparse factorisation's.
  std::vector<int> every(static_cast<std::size_t>(problem().numFreeDofs()));
  for (std::size_t j = 0; j < every.size(); ++j) every[j] = static_cast<int>(j);
  EXPECT_FALSE(stc::CholmodFactor(problem().stiffness_free, "K_ff", every, 0.0).condenses(z.B));
}
