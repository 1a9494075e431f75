// The linear-solver seam (src/linalg/spd_solver.hpp): one suite, instantiated for every backend this
// build has (cholmod always; mumps and cg-gamg with PETSc). Each backend solves K_ff of the seed scene
// and K + Bᵀ k B of the half-ball to its promise (round-off for a direct one, the relative residual
// for an iterative one), agrees with CHOLMOD, refuses a matrix with rigid motions (a direct one when
// it is prepared, an iterative one when a solve cannot reach its tolerance), and says what it has
// (no condensed operator but CHOLMOD's trailing block).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <Eigen/SparseLU>

#include <cmath>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/build_config.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/core/memory.hpp"
#include "stcontact/linalg/backends/cholmod_factor.hpp"
#include "stcontact/linalg/low_rank_solve.hpp"
#include "stcontact/linalg/prepare_spd_solver.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/operators/rigid_body_modes.hpp"
#include "stcontact/problem/problem.hpp"
#if STC_HAVE_PETSC
#include "stcontact/linalg/backends/petsc/petsc_solver.hpp"
#endif

namespace {

const stc::Problem& seed() {
  static const stc::Problem p = stc::buildProblem(stc::test::seedScene(31, 41));
  return p;
}

const stc::Problem& halfBall() {
  static const stc::Problem p = stc::buildProblem(stc::test::hemisphereScene(4, 5));
  return p;
}

// Random right-hand sides, from a seed (the same every run).
Eigen::MatrixXd randomRightHandSides(const stc::Problem& p, unsigned seed, int columns) {
  std::srand(seed);
  return Eigen::MatrixXd::Random(p.numFreeDofs(), columns);
}

// The iterative backends' relative residual in these tests: tight, so that they agree with CHOLMOD
// to 1e-6 on operators of condition number up to about 1e6.
constexpr double kRtol = 1e-12;

class SpdSolverBackend : public testing::TestWithParam<stc::LinearBackend> {
 protected:
  stc::LinearSolverOptions options() const {
    stc::LinearSolverOptions o;
    o.backend = GetParam();
    o.rtol = kRtol;
    o.max_iterations = 500;
    return o;
  }
  std::unique_ptr<stc::SpdSolver> prepare(const stc::Problem& p, const Eigen::SparseMatrix<double>& A) const {
    return stc::prepareSpdSolver(A, "A", options(), {{}, 1e8, [&p] { return stc::rigidBodyModesOfFreeDofs(p); }});
  }
  bool direct() const { return GetParam() != stc::LinearBackend::CgGamg; }
  // The bound on ‖A X − B‖ / ‖B‖ column by column: round-off, or the residual tolerance.
  double residualBound() const { return direct() ? 1e-10 : kRtol * 1.0001; }
};

// Column by column: ‖A x_j − b_j‖ / ‖b_j‖.
double worstRelativeResidual(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& X, const Eigen::MatrixXd& B) {
  const Eigen::SparseMatrix<double> full = A.selfadjointView<Eigen::Lower>();
  const Eigen::MatrixXd R = full * X - B;
  double worst = 0.0;
  for (Eigen::Index j = 0; j < B.cols(); ++j) worst = std::max(worst, R.col(j).norm() / B.col(j).norm());
  return worst;
}

}  // namespace

TEST_P(SpdSolverBackend, SolvesEveryColumnToItsPromise) {
  const auto& A = seed().stiffness_free;
  const auto solver = prepare(seed(), A);
  EXPECT_EQ(solver->size(), A.rows());
  EXPECT_EQ(solver->isDirect(), direct());
  const Eigen::MatrixXd B = randomRightHandSides(seed(), 5, 37);
  const Eigen::MatrixXd X = solver->solve(B);
  EXPECT_LE(worstRelativeResidual(A, X, B), residualBound());
  const Eigen::VectorXd x = solver->solve(Eigen::VectorXd(B.col(20)));
  EXPECT_LE((x - X.col(20)).norm(), 1e-9 * X.col(20).norm());
}

TEST_P(SpdSolverBackend, SolvesTheHalfBallsSearchOperatorAndAgreesWithCholmod) {
  const Eigen::SparseMatrix<double> A = stc::searchDirectionOperator(halfBall());
  const auto solver = prepare(halfBall(), A);
  const Eigen::MatrixXd B = randomRightHandSides(halfBall(), 7, 12);
  const Eigen::MatrixXd X = solver->solve(B);
  EXPECT_LE(worstRelativeResidual(A, X, B), residualBound());
  const Eigen::MatrixXd reference = stc::CholmodFactor(A, "A").solve(B);
  EXPECT_LE((X - reference).norm(), (direct() ? 1e-11 : 1e-6) * reference.norm());
  const stc::KrylovCounts counts = solver->krylovCounts();
  if (direct()) {
    EXPECT_EQ(counts.solves, 0);
  } else {  // one Krylov solve per column; GAMG with the rigid modes keeps them short
    EXPECT_EQ(counts.solves, 12);
    EXPECT_GT(counts.max_iterations, 0);
    EXPECT_LE(counts.max_iterations, 100);
  }
}

TEST_P(SpdSolverBackend, SolvesInPartsAsInOneBlock) {
  const auto solver = prepare(seed(), seed().stiffness_free);
  const Eigen::MatrixXd B = randomRightHandSides(seed(), 9, 20);
  std::vector<stc::SpdSolver::Workspace> workspaces;
  const Eigen::MatrixXd parts = solver->solveInParts(B, 4, workspaces);
  EXPECT_LE((parts - solver->solve(B)).norm(), 1e-9 * parts.norm());
  EXPECT_FALSE(workspaces.empty());
}

// Each column to its own loosened residual: a direct backend solves exactly as solve() (bit for bit:
// the same call), an iterative one stops each column within rtol ℓ_j (never past kLoosestRtol) and
// spends fewer iterations on the loosened ones than on tight ones. Loosenings below 1 or of another
// count are refused.
TEST_P(SpdSolverBackend, SolvesLoosenedColumnsEachToItsOwnResidual) {
  const Eigen::SparseMatrix<double> A = stc::searchDirectionOperator(halfBall());
  const auto solver = prepare(halfBall(), A);
  const Eigen::MatrixXd B = randomRightHandSides(halfBall(), 11, 3);
  const Eigen::MatrixXd B_twice = (Eigen::MatrixXd(B.rows(), 6) << B, B).finished();
  const Eigen::VectorXd loosening = (Eigen::VectorXd(6) << 1.0, 1.0, 1.0, 1e6, 1e6, 1e6).finished();
  const stc::KrylovCounts before = solver->krylovCounts();
  const Eigen::MatrixXd X = solver->solveLoosened(B_twice, loosening);
  if (direct()) {
    EXPECT_TRUE(X == solver->solve(B_twice));
  } else {
    EXPECT_LE(worstRelativeResidual(A, X.leftCols(3), B), kRtol * 1.0001);
    EXPECT_LE(worstRelativeResidual(A, X.rightCols(3), B), kRtol * 1e6 * 1.0001);
    const stc::KrylovCounts tight_then_loose = solver->krylovCounts();
    solver->solveLoosened(B, Eigen::VectorXd::Constant(3, 1e6));
    const long long loose = solver->krylovCounts().iterations - tight_then_loose.iterations;
    const long long tight = tight_then_loose.iterations - before.iterations - loose;
    std::cout << "[ measured ] Krylov iterations of 3 columns at 1e-12: " << tight << ", at 1e-6: " << loose << "\n";
    EXPECT_LT(4 * loose, 3 * tight) << "1e-6 against 1e-12: half the decades";
    // solve() is back at the prepared residual after a loosened call
    EXPECT_LE(worstRelativeResidual(A, solver->solve(B), B), kRtol * 1.0001);
  }
  // However loose asked, never past kLoosestRtol.
  const Eigen::MatrixXd far = solver->solveLoosened(B, Eigen::VectorXd::Constant(3, 1e12));
  EXPECT_LE(worstRelativeResidual(A, far, B), stc::LinearSolverOptions::kLoosestRtol * 1.0001);
  EXPECT_THROW(solver->solveLoosened(B, Eigen::VectorXd::Ones(2)), std::invalid_argument);
  EXPECT_THROW(solver->solveLoosened(B, Eigen::VectorXd::Constant(3, 0.5)), std::invalid_argument);
}

// C A⁻¹ Rᵀ M through the rank of M (src/linalg/low_rank_solve.hpp), M of 8 modes from 1 down to 1e-7:
// one solve per mode, the product of CHOLMOD's solve to 1e-9 relative on every backend (an iterative
// one loosens the small modes' residuals, and spends fewer iterations than on 8 tight solves).
TEST_P(SpdSolverBackend, SolvesThroughTheRankOfAGradedHistory) {
  const Eigen::SparseMatrix<double> A = stc::searchDirectionOperator(halfBall());
  const Eigen::SparseMatrix<double>& B = halfBall().contact.B;
  const auto solver = prepare(halfBall(), A);
  std::srand(13);
  const Eigen::MatrixXd U = Eigen::MatrixXd::Random(B.rows(), 8).householderQr().householderQ() *
                            Eigen::MatrixXd::Identity(B.rows(), 8);
  const Eigen::MatrixXd V = Eigen::MatrixXd::Random(20, 8).householderQr().householderQ() *
                            Eigen::MatrixXd::Identity(20, 8);
  Eigen::VectorXd sigma(8);
  for (int i = 0; i < 8; ++i) sigma[i] = std::pow(10.0, -i);
  const Eigen::MatrixXd M = U * sigma.asDiagonal() * V.transpose();
  long solves = 0;
  const stc::KrylovCounts before = solver->krylovCounts();
  const Eigen::MatrixXd lifted = stc::linalg::solveThroughRank(*solver, B, B, M, solves);
  const long long through_rank = solver->krylovCounts().iterations - before.iterations;
  const Eigen::MatrixXd exact = B * stc::CholmodFactor(A, "A").solve(Eigen::MatrixXd(B.transpose() * M));
  EXPECT_EQ(solves, 8);
  EXPECT_LE((lifted - exact).norm(), 1e-9 * exact.norm());
  if (direct()) return;
  solver->solve(Eigen::MatrixXd(B.transpose() * U));
  const long long tight = solver->krylovCounts().iterations - before.iterations - through_rank;
  std::cout << "[ measured ] Krylov iterations of 8 modes through the rank: " << through_rank << ", tight: " << tight << "\n";
  EXPECT_LT(through_rank, tight);
}

TEST_P(SpdSolverBackend, RefusesAMatrixWithRigidMotions) {
  const auto& K = seed().stiffness;  // no Dirichlet condition: singular
  if (direct()) {
    EXPECT_THROW(stc::prepareSpdSolver(K, "K", options(), {}), stc::InputError);
    return;
  }
  // An iterative backend prepares it; a right-hand side outside its range cannot be reached.
  stc::LinearSolverOptions o = options();
  o.max_iterations = 200;
  const auto solver = stc::prepareSpdSolver(K, "K", o, {});
  const Eigen::MatrixXd B = Eigen::MatrixXd::Ones(K.rows(), 1);  // a translation's load: not in the range
  try {
    solver->solve(B);
    ADD_FAILURE() << "a solve with K singular converged";
  } catch (const stc::LinearSolveFailure& failure) {
    EXPECT_NE(std::string(failure.what()).find("cg-gamg"), std::string::npos) << failure.what();
  }
}

TEST_P(SpdSolverBackend, RefusesARightHandSideOfAnotherSize) {
  const auto solver = prepare(seed(), seed().stiffness_free);
  EXPECT_THROW(solver->solve(Eigen::MatrixXd(Eigen::MatrixXd::Ones(3, 2))), std::invalid_argument);
}

TEST_P(SpdSolverBackend, HasTheCondensedOperatorOnlyFromCholmodsTrailingBlock) {
  const auto& A = seed().stiffness_free;
  std::vector<int> dofs(40);
  for (int i = 0; i < 40; ++i) dofs[static_cast<std::size_t>(i)] = i;
  const auto solver = stc::prepareSpdSolver(A, "A", options(), {dofs, 0.0, [] { return stc::rigidBodyModesOfFreeDofs(seed()); }});
  Eigen::SparseMatrix<double> C(1, A.rows());
  C.insert(0, 3) = 1.0;
  EXPECT_EQ(solver->condenses(C), GetParam() == stc::LinearBackend::Cholmod);
  if (!solver->condenses(C)) EXPECT_THROW(solver->condensed(C), std::invalid_argument);
}

// The held problem of solveHeld, solved directly: A with `replaced`'s rows, then the held rows made
// identity rows with x0's values on the right.
Eigen::VectorXd heldReference(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b,
                              const std::vector<int>& held, const Eigen::VectorXd& x0,
                              const stc::SpdSolver::ReplacedRows& replaced) {
  Eigen::SparseMatrix<double, Eigen::RowMajor> M = A.selfadjointView<Eigen::Lower>();
  Eigen::VectorXd rhs = b;
  for (std::size_t j = 0; j < replaced.dofs.size(); ++j) M.row(replaced.dofs[j]) = replaced.rows.row(static_cast<Eigen::Index>(j));
  for (int h : held) {
    M.row(h) *= 0.0;
    M.coeffRef(h, h) = 1.0;
    rhs[h] = x0[h];
  }
  Eigen::SparseMatrix<double> C = M;
  C.makeCompressed();
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(C);
  return lu.solve(rhs);
}

// solveHeld: cg-gamg alone holds dofs; it solves the Dirichlet problem A_FF x_F = b_F − A_FH x0_H
// (CG), and with a row replaced by a nonsymmetric one within its pattern (GMRES), to its relative
// residual (agreeing with a direct solve to 1e-6 at rtol 1e-12), the held entries x0's exactly.
TEST_P(SpdSolverBackend, HoldsDofsOnlyOnCgGamgWhereItSolvesTheHeldProblem) {
  const auto& A = seed().stiffness_free;
  const auto solver = prepare(seed(), A);
  EXPECT_EQ(solver->holdsDofs(), GetParam() == stc::LinearBackend::CgGamg);
  const auto n = static_cast<int>(A.rows());
  std::vector<int> held;
  for (int i = 3; i < n; i += 17) held.push_back(i);
  std::srand(11);
  const Eigen::VectorXd b = Eigen::VectorXd::Random(n), x0 = Eigen::VectorXd::Random(n);
  stc::SpdSolver::ReplacedRows replaced;
  if (!solver->holdsDofs()) {
    EXPECT_THROW(solver->solveHeld(b, held, x0, replaced), std::invalid_argument);
    return;
  }
  for (const bool nonsymmetric : {false, true}) {
    if (nonsymmetric) {  // row 0 with its off-diagonal entries 1.5 times A's: not A's column 0
      replaced.dofs = {0};
      Eigen::SparseMatrix<double, Eigen::RowMajor> full = A.selfadjointView<Eigen::Lower>();
      replaced.rows = full.topRows(1);
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(replaced.rows, 0); it; ++it)
        if (it.col() != 0) it.valueRef() *= 1.5;
    }
    const Eigen::VectorXd x = solver->solveHeld(b, held, x0, replaced);
    for (int h : held) EXPECT_EQ(x[h], x0[h]);
    const Eigen::VectorXd reference = heldReference(A, b, held, x0, replaced);
    EXPECT_LE((x - reference).norm(), 1e-6 * reference.norm()) << (nonsymmetric ? "GMRES" : "CG");
  }
  EXPECT_EQ(solver->krylovCounts().solves, 2);
  EXPECT_THROW(solver->solveHeld(Eigen::VectorXd::Ones(3), held, x0, {}), std::invalid_argument);
}

// Every backend this build has: cholmod, and the PETSc ones when PETSc was found (auto is one of
// them, chosen: below).
std::vector<stc::LinearBackend> builtBackends() {
  std::vector<stc::LinearBackend> out;
  for (const auto& [name, backend] : stc::kLinearBackends)
    if (backend == stc::LinearBackend::Cholmod ||
        (backend != stc::LinearBackend::Auto && stc::petscBackendsBuilt()))
      out.push_back(backend);
  return out;
}

INSTANTIATE_TEST_SUITE_P(Built, SpdSolverBackend, testing::ValuesIn(builtBackends()),
                         [](const testing::TestParamInfo<stc::LinearBackend>& info) {
                           for (const auto& [name, backend] : stc::kLinearBackends)
                             if (backend == info.param) {
                               std::string id(name);
                               std::erase(id, '-');
                               return id;
                             }
                           return std::string("unknown");
                         });

TEST(RigidBodyModes, AreKilledByTheUnconstrainedStiffness) {
  // K R = 0 for rigid motions of the whole body: checked on every dof free (the body without its
  // Dirichlet conditions), in 2D and 3D.
  for (const stc::Problem* p : {&seed(), &halfBall()}) {
    stc::Problem all = *p;
    all.free_dofs.resize(static_cast<std::size_t>(all.numDofs()));
    for (int i = 0; i < all.numDofs(); ++i) all.free_dofs[static_cast<std::size_t>(i)] = i;
    const Eigen::MatrixXd R = stc::rigidBodyModesOfFreeDofs(all);
    EXPECT_EQ(R.cols(), p->dimension == 2 ? 3 : 6);
    EXPECT_LE((R.transpose() * R - Eigen::MatrixXd::Identity(R.cols(), R.cols())).norm(), 1e-12);
    const Eigen::SparseMatrix<double> K = all.stiffness.selfadjointView<Eigen::Lower>();
    EXPECT_LE((K * R).norm(), 1e-9 * K.norm());
  }
}

// auto: CHOLMOD where its factor fits in half the memory available, else CG + GAMG; MUMPS on
// several ranks; CHOLMOD without PETSc.
TEST(AutoBackend, TakesTheDirectFactorWhereItFitsAndTheIterativeOneElsewhere) {
  using stc::LinearBackend;
  const double gb = 1e9;
  const stc::AutoBackend one = stc::autoBackend(1, true, 17 * gb);  // CHOLMOD, bounded by half of 17 GB
  EXPECT_EQ(one.backend, LinearBackend::Cholmod);
  EXPECT_LE(4 * gb, one.max_factor_bytes);  // a 4 GB factor is CHOLMOD's
  EXPECT_GT(9 * gb, one.max_factor_bytes);  // a 9 GB one gives way to CG + GAMG (CholmodFactorBound)
  const stc::AutoBackend ranks = stc::autoBackend(2, true, 17 * gb);  // MUMPS, bounded as CHOLMOD
  EXPECT_EQ(ranks.backend, LinearBackend::Mumps);
  EXPECT_EQ(ranks.max_factor_bytes, one.max_factor_bytes);
  EXPECT_TRUE(one.gives_way && ranks.gives_way);
  const stc::AutoBackend without_petsc = stc::autoBackend(1, false, 17 * gb);
  EXPECT_EQ(without_petsc.backend, LinearBackend::Cholmod);
  EXPECT_EQ(without_petsc.max_factor_bytes, 17 * gb);  // all of it: there is nothing to give way to,
  EXPECT_FALSE(without_petsc.gives_way);                // a factor beyond is refused (factorRefused)
  // In one process, the seed's K_ff fits: CHOLMOD, the same factor as asked by name.
  stc::LinearSolverOptions o;
  const auto chosen = stc::prepareSpdSolver(seed().stiffness_free, "K_ff", o, {});
  EXPECT_EQ(chosen->backend(), "cholmod");
  EXPECT_EQ(chosen->factorNonZeros(), stc::CholmodFactor(seed().stiffness_free, "K_ff").factorNonZeros());
}

TEST(CholmodFactorBound, RefusesAFactorAboveItsMemoryBoundBeforeAnyNumericalWork) {
  const auto& A = seed().stiffness_free;
  const double bytes = stc::CholmodFactor::bytesOf(stc::CholmodFactor(A, "K_ff").factorNonZeros());
  EXPECT_THROW(stc::CholmodFactor(A, "K_ff", {}, 1e8, 0.5 * bytes), stc::FactorTooLarge);
  EXPECT_NO_THROW(stc::CholmodFactor(A, "K_ff", {}, 1e8, 2.0 * bytes));
}

// A factor asked for by name that its analysis says would not fit is bad input: the error names
// solver.linear, the factor's size, the rank's memory and the backend that needs no factor.
TEST(CholmodFactorBound, AFactorAskedForByNameThatDoesNotFitIsRefusedNamingTheKey) {
  const auto& A = seed().stiffness_free;
  const double bytes = stc::CholmodFactor::bytesOf(stc::CholmodFactor(A, "K_ff").factorNonZeros());
  try {
    stc::CholmodFactor(A, "K_ff", {}, 1e8, 0.5 * bytes);
    FAIL() << "a factor above its bound was prepared";
  } catch (const stc::FactorTooLarge& refused) {
    const std::string message = stc::factorRefused(stc::LinearBackend::Cholmod, refused).what();
    EXPECT_THAT(message, ::testing::HasSubstr("solver.linear = \"cholmod\": the CHOLMOD factor of K_ff would take about"));
    EXPECT_THAT(message, ::testing::HasSubstr("more than the " + stc::bytesText(0.5 * bytes) + " allowed (what this rank may use)"));
    EXPECT_THAT(message, ::testing::HasSubstr("\"cg-gamg\" needs no factor"));
  }
}

// MUMPS's analysis estimates its factorisation's memory (INFOG(16)): beyond the bound, the factor is
// refused before the numerical work, and `auto`'s preparation on ranks gives way to CG + GAMG.
TEST(MumpsFactorBound, RefusesAFactorAboveItsMemoryBoundBeforeAnyNumericalWork) {
#if !STC_HAVE_PETSC
  GTEST_SKIP() << "a build without PETSc has no MUMPS";
#else
  const auto& A = seed().stiffness_free;
  stc::LinearSolverOptions o;
  o.backend = stc::LinearBackend::Mumps;
  EXPECT_THROW(stc::preparePetscSolver(A, "K_ff", o, {}, 1e3), stc::FactorTooLarge);  // 1 kB: no factor fits
  const auto fits = stc::preparePetscSolver(A, "K_ff", o, {}, 1e12);
  EXPECT_EQ(fits->backend(), "mumps");
  EXPECT_GT(fits->factorNonZeros(), 0.0);
#endif
}
