// The separated global stage (pgd/controlled_global_stage.hpp) and its response basis: the basis is
// k⁻¹-orthonormal with exact responses; the stage's iterate is in equilibrium, departs from the
// exact global stage by no more than its projection error (and no less than 1/√2 of it), and is
// the exact global stage once the directions span the right-hand sides; on a mid-sized zone its
// interface operator comes from the factor (no solve per direction), and from a share of its rows
// the directions are completed to span them all, after which the stage is exact.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fixtures/seed_scene.hpp"
#include "stcontact/build_config.hpp"
#include "stcontact/core/interruption.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/incremental/reach_zone.hpp"
#include "stcontact/latin/global_stage.hpp"
#include "stcontact/latin/indicator.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/linalg/backends/cholmod_factor.hpp"
#include "stcontact/linalg/prepare_spd_solver.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/pgd/controlled_global_stage.hpp"
#include "stcontact/pgd/separated_history.hpp"
#include "stcontact/problem/time_subgrid.hpp"

namespace {

struct Fixture {
  stc::Problem problem = stc::buildProblem(stc::test::seedScene(31, 41));
  stc::SolveResult reference = stc::solveIncremental(problem);
  /// A local-stage iterate near, not at, the solution.
  stc::InterfaceHistory hat() const {
    stc::InterfaceHistory s = reference.interface, h;
    s.lambda *= 0.8;
    stc::latin::localStage(problem.contact, s, h);
    return h;
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

double distance(const stc::Problem& p, const stc::InterfaceHistory& a, const stc::InterfaceHistory& b) {
  return std::sqrt(stc::latin::searchNormSquared(p.contact.search_direction, a.v - b.v, a.lambda - b.lambda));
}

// CG + GAMG to a relative residual of 1e-10: each direction its own solve, none condensed.
[[maybe_unused]] stc::LinearSolverOptions cgGamg() {
  stc::LinearSolverOptions linear;
  linear.backend = stc::LinearBackend::CgGamg;
  linear.rtol = 1e-10;
  return linear;
}

}  // namespace

TEST(ResponseBasis, DirectionsAreOrthonormalInTheInverseSearchProductAndResponsesExact) {
  const auto& f = fixture();
  stc::pgd::ControlledGlobalStage stage(f.problem, {});
  stc::InterfaceHistory s;
  stage.solve(f.hat(), s);  // first solve: enriches to a share of ‖w‖
  const stc::pgd::ResponseBasis& basis = stage.basis();
  ASSERT_GT(basis.size(), 0);
  const Eigen::MatrixXd& Z = basis.directions();
  const Eigen::MatrixXd gram = Z.transpose() * f.problem.contact.search_direction.cwiseInverse().asDiagonal() * Z;
  EXPECT_LE((gram - Eigen::MatrixXd::Identity(basis.size(), basis.size())).cwiseAbs().maxCoeff(), 1e-12);
  const Eigen::MatrixXd residual = stage.matrix() * basis.responses().gathered() - f.problem.contact.B.transpose() * Z;
  EXPECT_LE(residual.norm(), 1e-9 * (f.problem.contact.B.transpose() * Z).norm());
  EXPECT_LE((basis.traces() - f.problem.contact.B * basis.responses().gathered()).norm(), 1e-12 * basis.traces().norm());
}

// Candidates almost in the span of the directions (a warm start's, say) lose most of their norm in
// the first Gram–Schmidt pass; the second pass they then get keeps the basis orthonormal (one pass
// would leave them ~ε·10⁶ out of orthogonality here: the test fails with it switched off).
TEST(ResponseBasis, StaysOrthonormalWhenCandidatesLieMostlyInItsSpan) {
  const auto& f = fixture();
  stc::pgd::ControlledGlobalStage stage(f.problem, {});
  stc::InterfaceHistory s;
  stage.solve(f.hat(), s);
  const Eigen::MatrixXd Z = stage.basis().directions();
  std::srand(5);
  const Eigen::MatrixXd candidates =
      Z * Eigen::MatrixXd::Random(Z.cols(), 3) + 1e-6 * Eigen::MatrixXd::Random(Z.rows(), 3);
  ASSERT_EQ(stage.seed(candidates), 3);
  const Eigen::MatrixXd& all = stage.basis().directions();
  const Eigen::MatrixXd gram = all.transpose() * f.problem.contact.search_direction.cwiseInverse().asDiagonal() * all;
  EXPECT_LE((gram - Eigen::MatrixXd::Identity(all.cols(), all.cols())).cwiseAbs().maxCoeff(), 1e-12);
}

// Directions appended over several passes and solved in one block (what the stage's enrichment
// does) are those of append pass by pass, with the same responses to round-off; until solved they
// have no responses, traces or energy columns.
TEST(ResponseBasis, DirectionsSolvedInOneBlockAreThoseSolvedPassByPass) {
  const auto& f = fixture();
  const stc::CholmodFactor factor(stc::searchDirectionOperator(f.problem), "K + B^T k B");
  stc::pgd::ResponseBasis by_pass(f.problem, factor), in_block(f.problem, factor);
  std::srand(7);
  const Eigen::MatrixXd first = Eigen::MatrixXd::Random(f.problem.contact.rows(), 5);
  const Eigen::MatrixXd second = Eigen::MatrixXd::Random(f.problem.contact.rows(), 6);
  ASSERT_EQ(by_pass.append(first), 5);
  ASSERT_EQ(by_pass.append(second), 6);
  ASSERT_EQ(in_block.appendDirections(first), 5);
  ASSERT_EQ(in_block.appendDirections(second), 6);
  EXPECT_EQ(in_block.size(), 11);
  EXPECT_EQ(in_block.responses().cols(), 0);
  EXPECT_EQ(in_block.traces().cols(), 0);
  const long loads = in_block.sparseSolves();
  in_block.solvePending();
  EXPECT_EQ(in_block.sparseSolves(), loads + 11);
  EXPECT_EQ(in_block.sparseSolves(), by_pass.sparseSolves());
  EXPECT_TRUE(Eigen::MatrixXd(in_block.directions()) == Eigen::MatrixXd(by_pass.directions()));
  const Eigen::MatrixXd X = by_pass.responses().gathered();
  EXPECT_LE((in_block.responses().gathered() - X).norm(), 1e-12 * X.norm());
  EXPECT_EQ(in_block.energyFactor().size(), by_pass.energyFactor().size());
  EXPECT_EQ(in_block.energyFactor().rank(), by_pass.energyFactor().rank());
}

// Told where it is, a block of pending directions is solved on an iterative backend in parts of
// kProgressColumns, each part told as it ends, with the same responses and traces bit for bit (each
// column is its own solve); a direct factor solves the block at once, untold.
TEST(ResponseBasis, ABlockSolvedInToldPartsGivesTheSameResponses) {
  const auto& f = fixture();
  const Eigen::SparseMatrix<double> A = stc::searchDirectionOperator(f.problem);
  std::vector<std::unique_ptr<stc::SpdSolver>> factors;
  factors.push_back(std::make_unique<stc::CholmodFactor>(A, "K + B^T k B"));
#if STC_HAVE_PETSC
  stc::LinearSolverOptions cg;
  cg.backend = stc::LinearBackend::CgGamg;
  cg.rtol = 1e-10;
  factors.push_back(stc::prepareSpdSolver(A, "K + B^T k B", cg, {}));
#endif
  for (const auto& factor : factors) {
    stc::pgd::ResponseBasis silent(f.problem, *factor), told(f.problem, *factor);
    std::srand(11);
    const Eigen::MatrixXd candidates = Eigen::MatrixXd::Random(f.problem.contact.rows(), 37);
    ASSERT_EQ(silent.appendDirections(candidates), 37);
    ASSERT_EQ(told.appendDirections(candidates), 37);
    silent.solvePending();
    std::vector<std::pair<Eigen::Index, Eigen::Index>> lines;
    told.solvePending(Eigen::VectorXd(), [&](Eigen::Index solved, Eigen::Index pending) { lines.emplace_back(solved, pending); });
    using Parts = std::vector<std::pair<Eigen::Index, Eigen::Index>>;
    const Parts parts = factor->isDirect() ? Parts{} : Parts{{16, 37}, {32, 37}, {37, 37}};
    EXPECT_EQ(lines, parts) << factor->backend();
    EXPECT_TRUE(told.responses().gathered() == silent.responses().gathered()) << factor->backend();
    EXPECT_TRUE(Eigen::MatrixXd(told.traces()) == Eigen::MatrixXd(silent.traces())) << factor->backend();
    EXPECT_EQ(told.sparseSolves(), silent.sparseSolves());
  }
}

// A stage told to note its phases says where a long enrichment is (here every part: interval 0),
// and solves as a silent one does, bit for bit. On CG + GAMG, where each direction is a solve (a
// factor that condenses the interface gives the traces with none, and has nothing to tell).
TEST(ControlledGlobalStage, NotesWhereItsEnrichmentIsAndSolvesAsASilentOne) {
#if !STC_HAVE_PETSC
  GTEST_SKIP() << "without PETSc the factor condenses the interface: no solve per direction to tell";
#else
  const auto& f = fixture();
  stc::PreparedOperators operators(cgGamg());
  stc::pgd::ControlledGlobalStage silent(f.problem, {}, operators), noted(f.problem, {}, operators);
  ASSERT_FALSE(noted.basis().condensesInterface());
  std::vector<std::string> lines;
  noted.notePhases([&](const std::string& line) { lines.push_back(line); }, 0.0);
  stc::InterfaceHistory a, b;
  silent.solve(f.hat(), a);
  noted.solve(f.hat(), b);
  EXPECT_TRUE(a.v == b.v && a.lambda == b.lambda);
  ASSERT_FALSE(lines.empty());
  const std::string last = "global stage: " + std::to_string(noted.basis().size()) + " of " +
                           std::to_string(noted.basis().size()) + " new directions solved (" +
                           std::to_string(noted.basis().size()) + " in all), ";
  EXPECT_EQ(lines.back().rfind(last, 0), 0u) << lines.back();
#endif
}

// A caller's stop (src/core/interruption.hpp, StopProbe) is heard between the parts of a long solve
// of directions, which makes no record: on CG + GAMG, where each direction is a solve, seeding 40
// directions throws stc::Interrupted after the first part of ResponseBasis::kProgressColumns, the
// other directions left unsolved.
TEST(ControlledGlobalStage, HearsACallersStopBetweenThePartsOfItsDirections) {
#if !STC_HAVE_PETSC
  GTEST_SKIP() << "without PETSc the factor condenses the interface: no solve per direction to stop between";
#else
  const auto& f = fixture();
  stc::PreparedOperators operators(cgGamg());
  stc::pgd::ControlledGlobalStage stage(f.problem, {}, operators);
  int asked = 0;
  const stc::StopProbe probe([&] { return ++asked < 1; });
  const Eigen::MatrixXd seeds = Eigen::MatrixXd::Random(f.problem.contact.rows(), 40);
  EXPECT_THROW(stage.seed(seeds), stc::Interrupted);
  EXPECT_EQ(asked, 1);
  long long solved = 0;
  for (const stc::Preparation& p : operators.preparations()) solved += p.krylov.solves;
  EXPECT_EQ(solved, stage.basis().loadResponses().cols() + stc::pgd::ResponseBasis::kProgressColumns);
#endif
}

// With the interface's dofs ordered last, the factor's trailing block gives D = B A⁻¹ Bᵀ and the
// traces T = D Z with no solve: the same traces and energy factor as the solves' to round-off; the
// responses are solved when asked for, and the displacements of other rows through the rank of the
// history (at most its m instants), both as the solved basis gives them.
TEST(ResponseBasis, TracesFromTheFactorsTrailingBlockAreThoseOfTheSolves) {
  const auto& f = fixture();
  const Eigen::SparseMatrix<double> A = stc::searchDirectionOperator(f.problem);
  const stc::CholmodFactor plain(A, "K + B^T k B"), last(A, "K + B^T k B", stc::dofsReadBy(f.problem.contact.B), 0.0);
  stc::pgd::ResponseBasis solved(f.problem, plain), condensed(f.problem, last);
  EXPECT_FALSE(solved.condensesInterface());
  ASSERT_TRUE(condensed.condensesInterface());
  const long loads = condensed.sparseSolves();
  std::srand(11);
  const Eigen::MatrixXd candidates = Eigen::MatrixXd::Random(f.problem.contact.rows(), 11);
  ASSERT_EQ(solved.append(candidates), 11);
  ASSERT_EQ(condensed.append(candidates), 11);
  EXPECT_EQ(condensed.sparseSolves(), loads);
  EXPECT_EQ(solved.sparseSolves(), loads + 11);
  const Eigen::MatrixXd T = solved.traces();
  EXPECT_LE((Eigen::MatrixXd(condensed.traces()) - T).norm(), 1e-12 * T.norm());
  EXPECT_EQ(condensed.energyFactor().rank(), solved.energyFactor().rank());
  // Other rows: the first nodes' B rows; a history of rank 3 over the 41 instants.
  const Eigen::SparseMatrix<double> B_rows = stc::restrictToNodes(f.problem.contact, {0, 1, 2, 3}).B;
  const Eigen::MatrixXd c = Eigen::MatrixXd::Random(11, 3) * Eigen::MatrixXd::Random(3, f.problem.numSteps());
  const Eigen::MatrixXd v = solved.displacementOn(B_rows, c);
  EXPECT_LE((condensed.displacementOn(B_rows, c) - v).norm(), 1e-10 * v.norm());
  EXPECT_EQ(condensed.sparseSolves(), loads + 3);
  const Eigen::MatrixXd X = solved.responses().gathered();
  EXPECT_LE((condensed.responses().gathered() - X).norm(), 1e-12 * X.norm());
  EXPECT_EQ(condensed.sparseSolves(), loads + 3 + 11);
}

// Where the factor does not condense the interface, the responses are kept while they fit in the
// bytes the basis was given (here 11 columns of n_free doubles) and released beyond (the 12th): the
// traces and energy factor are those of a basis that keeps them, bitwise (the same solves); what
// needs X afterwards solves it again, to the solves' accuracy, through the rank of what it asks for.
TEST(ResponseBasis, ReleasesItsResponsesBeyondItsBytesAndSolvesThemAgainWhenAsked) {
  const auto& f = fixture();
  const Eigen::SparseMatrix<double> A = stc::searchDirectionOperator(f.problem);
  const stc::CholmodFactor plain(A, "K + B^T k B");
  const double eleven = 11.0 * sizeof(double) * f.problem.numFreeDofs();
  stc::pgd::ResponseBasis kept(f.problem, plain), bounded(f.problem, plain, eleven);
  std::srand(19);
  const Eigen::MatrixXd candidates = Eigen::MatrixXd::Random(f.problem.contact.rows(), 12);
  ASSERT_EQ(kept.append(candidates.leftCols(11)), 11);
  ASSERT_EQ(kept.append(candidates.rightCols(1)), 1);
  ASSERT_EQ(bounded.append(candidates.leftCols(11)), 11);
  EXPECT_TRUE(bounded.holdsResponses());
  ASSERT_EQ(bounded.append(candidates.rightCols(1)), 1);
  EXPECT_FALSE(bounded.holdsResponses());
  EXPECT_THROW(bounded.responses(), std::logic_error);
  EXPECT_TRUE(Eigen::MatrixXd(bounded.traces()) == Eigen::MatrixXd(kept.traces()));
  EXPECT_EQ(bounded.energyFactor().rank(), kept.energyFactor().rank());
  const long solves = bounded.sparseSolves();
  EXPECT_EQ(solves, kept.sparseSolves());
  // The displacement of other rows from a history of rank 3: 3 solves again.
  const Eigen::SparseMatrix<double> B_rows = stc::restrictToNodes(f.problem.contact, {0, 1, 2, 3}).B;
  const Eigen::MatrixXd c = Eigen::MatrixXd::Random(12, 3) * Eigen::MatrixXd::Random(3, f.problem.numSteps());
  const Eigen::MatrixXd v = kept.displacementOn(B_rows, c);
  EXPECT_LE((bounded.displacementOn(B_rows, c) - v).norm(), 1e-10 * v.norm());
  EXPECT_EQ(bounded.sparseSolves(), solves + 3);
  EXPECT_EQ(kept.sparseSolves(), solves);
  // Two modes' responses, and the spatial modes of every direction: one solve per column asked.
  const Eigen::MatrixXd M = Eigen::MatrixXd::Random(12, 2);
  const Eigen::MatrixXd XM = kept.responsesOf(M);
  EXPECT_LE((bounded.responsesOf(M) - XM).norm(), 1e-10 * XM.norm());
  EXPECT_EQ(bounded.sparseSolves(), solves + 5);
  const Eigen::MatrixXd combination = Eigen::MatrixXd::Random(kept.loadResponses().cols() + 12, 4);
  const Eigen::MatrixXd Y = stc::pgd::spatialModes(kept, combination);
  EXPECT_LE((stc::pgd::spatialModes(bounded, combination) - Y).norm(), 1e-10 * Y.norm());
  EXPECT_EQ(bounded.sparseSolves(), solves + 9);
}

// The responses are kept in the blocks they were solved in, so that appending copies nothing held:
// with room for exactly 12 columns, 12 directions appended one at a time keep all 12 (storage grown
// by doubling held 8 + 16 columns while the 9th came), and the 13th releases them.
TEST(ResponseBasis, KeepsItsResponsesWhileTheyFitExactly) {
  const auto& f = fixture();
  const Eigen::SparseMatrix<double> A = stc::searchDirectionOperator(f.problem);
  const stc::CholmodFactor plain(A, "K + B^T k B");
  const double twelve = 12.0 * sizeof(double) * f.problem.numFreeDofs();
  stc::pgd::ResponseBasis bounded(f.problem, plain, twelve);
  std::srand(23);
  const Eigen::MatrixXd candidates = Eigen::MatrixXd::Random(f.problem.contact.rows(), 13);
  for (int j = 0; j < 12; ++j) ASSERT_EQ(bounded.append(candidates.col(j)), 1);
  ASSERT_TRUE(bounded.holdsResponses());
  EXPECT_EQ(bounded.responses().cols(), 12);
  EXPECT_EQ(bounded.responses().bytes(), twelve);
  ASSERT_EQ(bounded.append(candidates.col(12)), 1);
  EXPECT_FALSE(bounded.holdsResponses());
}

// The traces on other rows kept as each response is solved (the far nodes of a zone): once X is
// released, their displacement is that of the basis keeping X, with no solve; asked for after the
// first direction they are refused, and a factor that condenses the interface keeps none (its
// directions solve no response).
TEST(ResponseBasis, TracesKeptOnOtherRowsGiveTheirDisplacementWithNoSolve) {
  const auto& f = fixture();
  const Eigen::SparseMatrix<double> A = stc::searchDirectionOperator(f.problem);
  const stc::CholmodFactor plain(A, "K + B^T k B"), last(A, "K + B^T k B", stc::dofsReadBy(f.problem.contact.B), 0.0);
  const Eigen::SparseMatrix<double> B_rows = stc::restrictToNodes(f.problem.contact, {0, 1, 2, 3}).B;
  const double eleven = 11.0 * sizeof(double) * f.problem.numFreeDofs();
  stc::pgd::ResponseBasis kept(f.problem, plain), traced(f.problem, plain, eleven), condensed(f.problem, last);
  traced.keepTracesOn(B_rows);
  condensed.keepTracesOn(B_rows);
  EXPECT_FALSE(condensed.keepsTracesFor(0));
  std::srand(29);
  const Eigen::MatrixXd candidates = Eigen::MatrixXd::Random(f.problem.contact.rows(), 12);
  ASSERT_EQ(kept.append(candidates), 12);
  ASSERT_EQ(traced.append(candidates.leftCols(5)), 5);
  ASSERT_EQ(traced.append(candidates.rightCols(7)), 7);
  ASSERT_FALSE(traced.holdsResponses());
  ASSERT_TRUE(traced.keepsTracesFor(12));
  EXPECT_THROW(kept.keepTracesOn(B_rows), std::logic_error);
  const Eigen::MatrixXd c = Eigen::MatrixXd::Random(12, f.problem.numSteps());
  const long solves = traced.sparseSolves();
  const Eigen::MatrixXd v = kept.displacementOn(B_rows, c);
  EXPECT_LE((traced.displacementOnKeptRows(c) - v).norm(), 1e-12 * v.norm());
  EXPECT_EQ(traced.sparseSolves(), solves);
  EXPECT_THROW(condensed.displacementOnKeptRows(c.topRows(0)), std::logic_error);
}

// Completed to span every row (from 11 directions), the basis stays k⁻¹-orthonormal, its traces are
// D Z = B A⁻¹ Bᵀ Z (checked against solves), its energy factor covers every column, and no sparse
// solve was made. A basis whose factor does not give D refuses.
TEST(ResponseBasis, CompletedToEveryRowIsOrthonormalWithTheTracesOfD) {
  const auto& f = fixture();
  const Eigen::SparseMatrix<double> A = stc::searchDirectionOperator(f.problem);
  const stc::CholmodFactor plain(A, "K + B^T k B"), last(A, "K + B^T k B", stc::dofsReadBy(f.problem.contact.B), 0.0);
  stc::pgd::ResponseBasis solved(f.problem, plain), condensed(f.problem, last);
  EXPECT_THROW(solved.completeToEveryRow(), std::logic_error);
  std::srand(13);
  const int n = f.problem.contact.rows();
  ASSERT_EQ(condensed.append(Eigen::MatrixXd::Random(n, 11)), 11);
  const Eigen::MatrixXd before = condensed.directions();
  const long loads = condensed.sparseSolves();
  condensed.completeToEveryRow();
  ASSERT_EQ(condensed.size(), n);
  EXPECT_EQ(condensed.sparseSolves(), loads);
  EXPECT_TRUE(Eigen::MatrixXd(condensed.directions().leftCols(11)) == before);  // the first ones kept
  const Eigen::MatrixXd Zs = condensed.scaledDirections();
  EXPECT_LE((Zs.transpose() * Zs - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff(), 1e-12);
  const Eigen::MatrixXd Z = condensed.directions();
  const Eigen::MatrixXd T = f.problem.contact.B * plain.solve(Eigen::MatrixXd(f.problem.contact.B.transpose() * Z));
  EXPECT_LE((Eigen::MatrixXd(condensed.traces()) - T).norm(), 1e-10 * T.norm());
  EXPECT_EQ(condensed.energyFactor().size(), condensed.loadResponses().cols() + n);
  condensed.completeToEveryRow();  // already complete: nothing changes
  EXPECT_EQ(condensed.size(), n);
}

// The displacement history truncated in energy (a lift that spends a budget): its A-energy from the
// whole history, Σ_k δu_kᵀ A δu_k with A assembled, is within the budget; it makes fewer solves than
// the history's rank; no budget gives the exact lift bitwise, a budget above the whole energy gives
// zero with no solve, and no row to lift to no solve at all. B_rows = I: the whole free field.
TEST(ResponseBasis, DisplacementTruncatedInEnergyStaysWithinItsBudget) {
  const auto& f = fixture();
  const Eigen::SparseMatrix<double> A = stc::searchDirectionOperator(f.problem);
  const stc::CholmodFactor last(A, "K + B^T k B", stc::dofsReadBy(f.problem.contact.B), 0.0);
  stc::pgd::ResponseBasis basis(f.problem, last);
  ASSERT_TRUE(basis.condensesInterface());
  std::srand(17);
  ASSERT_EQ(basis.append(Eigen::MatrixXd::Random(f.problem.contact.rows(), 12)), 12);
  // A history of rank 12 whose modes decay by 10 per mode.
  const int m = f.problem.numSteps();
  const Eigen::VectorXd decay = Eigen::VectorXd::LinSpaced(12, 0.0, -11.0).unaryExpr([](double e) { return std::pow(10.0, e); });
  const Eigen::MatrixXd c = Eigen::MatrixXd::Random(12, 12) * decay.asDiagonal() * Eigen::MatrixXd::Random(12, m);
  Eigen::SparseMatrix<double> I(f.problem.numFreeDofs(), f.problem.numFreeDofs());
  I.setIdentity();
  const auto energy = [&](const Eigen::MatrixXd& u) { return (u.transpose() * A * u).trace(); };
  long before = basis.sparseSolves();
  const Eigen::MatrixXd u = basis.displacementOn(I, c);
  const long exact_solves = basis.sparseSolves() - before;
  EXPECT_EQ(exact_solves, 12);
  EXPECT_TRUE(basis.displacementOn(I, c, 0.0) == u);
  for (const double share : {1e-4, 1e-10, 1e-16}) {
    const double budget = share * energy(u);
    before = basis.sparseSolves();
    const Eigen::MatrixXd truncated = basis.displacementOn(I, c, budget);
    const long solves = basis.sparseSolves() - before;
    EXPECT_LE(energy(u - truncated), budget * (1 + 1e-6) + 1e-14 * energy(u)) << share;
    EXPECT_LT(solves, exact_solves) << share;
    EXPECT_GE(solves, 1) << share;
  }
  before = basis.sparseSolves();
  EXPECT_EQ(basis.displacementOn(I, c, 2.0 * energy(u)).norm(), 0.0);
  EXPECT_EQ(basis.sparseSolves(), before);
  // No row to lift to (a solve on the whole interface leaves no node out): no solve either way.
  const Eigen::SparseMatrix<double> none(0, f.problem.numFreeDofs());
  EXPECT_EQ(basis.displacementOn(none, c).size(), 0);
  EXPECT_EQ(basis.displacementOn(none, c, 1e-4 * energy(u)).size(), 0);
  EXPECT_EQ(basis.sparseSolves(), before);
}

TEST(ControlledGlobalStage, DepartsFromTheExactStageByItsProjectionError) {
  const auto& f = fixture();
  stc::latin::GlobalStage exact(f.problem);
  stc::pgd::ControlledGlobalStage stage(f.problem, {});
  const stc::InterfaceHistory hat = f.hat();
  stc::InterfaceHistory s_exact, s;
  exact.solve(hat, s_exact);
  stage.observeGap(1.0);  // a loose bound: the projection leaves an error
  stage.solve(hat, s);
  const double error = stage.projectionError(), gap = distance(f.problem, s, s_exact);
  ASSERT_GT(error, 0.0);
  EXPECT_LE(gap, error * (1 + 1e-9));
  EXPECT_GE(gap, error / std::sqrt(2.0) * (1 - 1e-9));
}

TEST(ControlledGlobalStage, IsInEquilibrium) {
  // K_ff u = F g + Bᵀ λ with u = U_F g + X c: v = B u, and λ + k v = Z c (docs/method.md §5).
  const auto& f = fixture();
  stc::pgd::ControlledGlobalStage stage(f.problem, {});
  stage.observeGap(1.0);
  stc::InterfaceHistory s;
  stage.solve(f.hat(), s);
  const auto& basis = stage.basis();
  const Eigen::MatrixXd u = basis.loadResponses() * basis.loadHistories() + basis.responses().times(stage.coordinates());
  EXPECT_LE((f.problem.contact.B * u - s.v).norm(), 1e-12 * s.v.norm());
  const Eigen::MatrixXd lhs = f.problem.stiffness_free * u;
  const Eigen::MatrixXd rhs = f.problem.loadBlock(0, f.problem.numSteps()) + f.problem.contact.B.transpose() * s.lambda;
  EXPECT_LE((lhs - rhs).norm(), 1e-9 * rhs.norm());
}

TEST(ControlledGlobalStage, IsTheExactStageWhenTheDirectionsSpanTheRightHandSides) {
  const auto& f = fixture();
  stc::latin::GlobalStage exact(f.problem);
  stc::pgd::ControlledGlobalStage stage(f.problem, {});
  const stc::InterfaceHistory hat = f.hat();
  stc::InterfaceHistory s_exact, s;
  exact.solve(hat, s_exact);
  stage.observeGap(0.0);  // no error allowed: enrich until w is spanned
  stage.solve(hat, s);
  EXPECT_LE(stage.projectionError(), 1e-10 * distance(f.problem, s_exact, stc::InterfaceHistory::zeros(f.problem.contact, 41)));
  EXPECT_LE(distance(f.problem, s, s_exact), 1e-9 * distance(f.problem, s_exact, stc::InterfaceHistory::zeros(f.problem.contact, 41)));
  EXPECT_LE(stage.rank(), 2 * f.problem.contact.size());
}

TEST(ControlledGlobalStage, AnticipatesTheCoordinatesOfItsNextSolve) {
  // anticipate(ŝ) enriches as solve(ŝ) would and returns that solve's coordinates, leaving the last
  // solve's iterate alone; the solve that follows then needs no new direction.
  const auto& f = fixture();
  stc::pgd::ControlledGlobalStage stage(f.problem, {});
  stc::InterfaceHistory s, first = stc::InterfaceHistory::zeros(f.problem.contact, f.problem.numSteps());
  first.lambda = 0.3 * f.reference.interface.lambda;  // a first right-hand side, far from the next
  stage.solve(first, s);
  stage.observeGap(1e-2 * distance(f.problem, s, first));
  const Eigen::MatrixXd c_first = stage.coordinates();
  const int rank_first = stage.rank();
  const stc::InterfaceHistory hat = f.hat();
  const Eigen::MatrixXd anticipated = stage.anticipate(hat);
  ASSERT_GT(stage.rank(), rank_first);  // the next right-hand side needed new directions
  EXPECT_EQ(stage.coordinates(), c_first);
  EXPECT_EQ(anticipated.rows(), stage.rank());
  const int rank_anticipated = stage.rank();
  stage.solve(hat, s);
  EXPECT_EQ(stage.rank(), rank_anticipated);
  // The solve projects w on all directions at once, the anticipation on the old ones and then the
  // new ones on what the old left (k⁻¹-orthogonal to the old: equal up to round-off).
  EXPECT_LE((stage.coordinates() - anticipated).norm(), 1e-10 * anticipated.norm());
}

// Retimed to every 4th instant, the stage is the sub-grid's own (the same free response, the same
// iterate from the same local stage, the directions kept); retimed back, the whole grid's. A problem
// with other load vectors is refused.
TEST(ControlledGlobalStage, RetimedIsTheStageOfTheOtherGrid) {
  const auto& f = fixture();
  const std::vector<int> kept = stc::everyNthInstant(f.problem.numSteps(), 4);
  const stc::Problem sub = stc::onInstants(f.problem, kept);
  stc::pgd::ControlledGlobalStage stage(f.problem, {});
  stc::InterfaceHistory s;
  stage.solve(f.hat(), s);
  const int directions = stage.rank();
  const Eigen::MatrixXd whole_free = stage.basis().freeResponse();
  stage.retime(sub);
  EXPECT_EQ(stage.rank(), directions);
  stc::pgd::ControlledGlobalStage own(sub, {});
  ASSERT_EQ(stage.basis().freeResponse().cols(), sub.numSteps());
  EXPECT_LE((stage.basis().freeResponse() - own.basis().freeResponse()).norm(), 1e-12 * whole_free.norm());
  EXPECT_EQ(stage.basis().freeResponse(), whole_free(Eigen::all, kept));
  // The same directions in `own`: both give the same iterate from a sub-grid local stage.
  own.seed(stage.basis().directions());
  const stc::InterfaceHistory h = f.hat(), h_sub{h.v(Eigen::all, kept), h.lambda(Eigen::all, kept)};
  stc::InterfaceHistory a, b;
  stage.solve(h_sub, a);
  own.solve(h_sub, b);
  EXPECT_LE(distance(sub, a, b), 1e-9 * std::sqrt(stc::latin::searchNormSquared(sub.contact.search_direction, b.v, b.lambda)));
  stage.retime(f.problem);
  EXPECT_EQ(stage.basis().freeResponse(), whole_free);
  const stc::Problem other = stc::buildProblem(stc::test::seedScene(21, 41));
  EXPECT_THROW(stage.retime(other), std::invalid_argument);
}

// The separated stage orders its interface's dofs last at every size CholmodFactor's bounds allow,
// the incremental solver's factor only from CholmodFactor::kTrailingWork: the stage saves a solve for
// every direction it adds, not only the |J| of one Delassus operator. On the zone within reach of
// the seed mesh (101 arc nodes, 58 rows, |J| · lnz ≈ 1e6) its directions' traces come from the
// trailing block, while the incremental solver's factor of the same dofs stays plain.
TEST(ControlledGlobalStage, CondensesEvenTheSeedsZoneWhereTheIncrementalSolverDoesNot) {
  stc::Problem problem = stc::buildProblem(stc::test::seedScene(101, 3));
  const std::optional<std::vector<int>> zone = stc::reachZone(problem);
  ASSERT_TRUE(zone);
  problem.contact = stc::restrictToNodes(problem.contact, *zone);
  ASSERT_EQ(problem.contact.rows(), 58);
  const stc::pgd::ControlledGlobalStage stage(problem, {});
  EXPECT_TRUE(stage.basis().condensesInterface());
  const stc::CholmodFactor incremental(problem.stiffness_free, "K_ff", stc::dofsReadBy(problem.contact.B));
  EXPECT_FALSE(incremental.condenses(problem.contact.B));
}

// From ControlledStageOptions::full_share of its rows (here 0.5 %: 3 of the zone's 462) the stage
// completes its directions (no sparse solve) and is then the exact global stage, v = V_F G + D w;
// its coordinates, formed when asked for, give v through the traces, and the anticipation of the
// same right-hand side gives them too.
TEST(ControlledGlobalStage, SpansEveryRowFromItsShareAndIsThenTheExactStage) {
  stc::Problem problem = stc::buildProblem(stc::test::seedScene(801, 3));
  const std::optional<std::vector<int>> zone = stc::reachZone(problem);
  ASSERT_TRUE(zone);
  problem.contact = stc::restrictToNodes(problem.contact, *zone);
  const int n = problem.contact.rows(), m = problem.numSteps();
  stc::pgd::ControlledStageOptions options;
  options.full_share = 0.005;
  stc::pgd::ControlledGlobalStage stage(problem, options);
  ASSERT_TRUE(stage.basis().condensesInterface());
  std::srand(17);
  stc::InterfaceHistory first{1e-3 * Eigen::MatrixXd::Random(n, m), Eigen::MatrixXd::Random(n, m)}, s;
  stage.solve(first, s);
  ASSERT_FALSE(stage.spansEveryRow());
  ASSERT_GE(stage.rank(), 3);  // the rank of w: its 3 instants
  ASSERT_LT(stage.rank(), n);
  const long solves = stage.sparseSolves();
  const stc::InterfaceHistory hat{1e-3 * Eigen::MatrixXd::Random(n, m), Eigen::MatrixXd::Random(n, m)};
  stage.solve(hat, s);
  EXPECT_TRUE(stage.spansEveryRow());
  EXPECT_EQ(stage.rank(), n);
  EXPECT_EQ(stage.sparseSolves(), solves);
  EXPECT_EQ(stage.projectionError(), 0.0);
  stc::latin::GlobalStage exact(problem);
  stc::InterfaceHistory s_exact;
  exact.solve(hat, s_exact);
  const double size = distance(problem, s_exact, stc::InterfaceHistory::zeros(problem.contact, m));
  EXPECT_LE(distance(problem, s, s_exact), 1e-9 * size);
  const Eigen::MatrixXd c = stage.coordinates();
  ASSERT_EQ(c.rows(), n);
  const Eigen::MatrixXd v = stage.basis().freeResponse() + stage.basis().traces() * c;
  EXPECT_LE((v - s.v).norm(), 1e-10 * s.v.norm());
  EXPECT_LE((stage.anticipate(hat) - c).norm(), 1e-12 * c.norm());
  // The whitened anticipation formed from R_Z Z̃ᵀ is the whitening of the anticipated coordinates.
  const stc::pgd::EnergyFactor& factor = stage.basis().energyFactor();
  const Eigen::MatrixXd whitened = factor.whiten(stc::pgd::historyFactor(stage.basis(), stage.anticipate(hat)));
  EXPECT_LE((stage.anticipateWhitened(hat).whitened - whitened).norm(), 1e-10 * whitened.norm());
  // Its step, in the same product: the sketched difference of the next and the last histories'
  // energy coordinates.
  const stc::InterfaceHistory next{1e-3 * Eigen::MatrixXd::Random(n, m), Eigen::MatrixXd::Random(n, m)};
  const auto anticipated = stage.anticipateWhitened(next, 2);
  const Eigen::MatrixXd last = factor.whiten(stc::pgd::historyFactor(stage.basis(), c));
  const Eigen::MatrixXd step = (anticipated.whitened - last) * stc::pgd::ControlledGlobalStage::stepSketch(m, 2);
  ASSERT_EQ(anticipated.step.cols(), 2);
  EXPECT_LE((anticipated.step - step).norm(), 1e-10 * step.norm());
}

// The step of the next solve (anticipateWhitened with step samples): none before a solve; after
// one, the sketched difference R [0; c_next − c_last] Ω of the anticipated and the last histories'
// energy coordinates, the last solve's coordinates zero on the directions the anticipation added.
TEST(ControlledGlobalStage, SketchesTheStepOfItsNextSolveInEnergyCoordinates) {
  const auto& f = fixture();
  const int m = f.problem.numSteps();
  stc::pgd::ControlledGlobalStage stage(f.problem, {});
  stc::InterfaceHistory s, first = stc::InterfaceHistory::zeros(f.problem.contact, m);
  first.lambda = 0.3 * f.reference.interface.lambda;
  EXPECT_EQ(stage.anticipateWhitened(first, 3).step.size(), 0);
  stage.solve(first, s);
  stage.observeGap(1e-2 * distance(f.problem, s, first));
  const Eigen::MatrixXd c_last = stage.coordinates();
  const int rank_last = stage.rank();
  const auto anticipated = stage.anticipateWhitened(f.hat(), 3);
  ASSERT_GT(stage.rank(), rank_last);  // the step reaches directions the last solve did not have
  EXPECT_EQ(stage.anticipateWhitened(f.hat(), 0).step.size(), 0);
  const Eigen::MatrixXd last = stage.basis().energyFactor().whiten(stc::pgd::historyFactor(stage.basis(), c_last));
  const Eigen::MatrixXd step = (anticipated.whitened - last) * stc::pgd::ControlledGlobalStage::stepSketch(m, 3);
  ASSERT_EQ(anticipated.step.rows(), anticipated.whitened.rows());
  ASSERT_EQ(anticipated.step.cols(), 3);
  EXPECT_GT(step.norm(), 0.0);
  EXPECT_LE((anticipated.step - step).norm(), 1e-10 * step.norm());
}
