// `latin-pgd` and `fas-apriori` against the incremental solver (docs/method.md §5), on a small seed
// scene; the a priori coarse space; the tolerance as a bound on the true error for every iterative
// strategy.
#include <gtest/gtest.h>

#include <Eigen/QR>

#include <iostream>
#include <string>

#include "fixtures/seed_scene.hpp"
#include "stcontact/fas/apriori/apriori_basis.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/pgd/controlled_global_stage.hpp"
#include "stcontact/pgd/separated_history.hpp"
#include "strategies/strategy_fixture.hpp"

namespace {

const stc::test::StrategyFixture& fixture() {
  static const stc::test::StrategyFixture f(stc::test::seedScene(31, 41));
  return f;
}

stc::SolveResult solve(const std::string& name, double tolerance) { return fixture().solve(name, tolerance); }

}  // namespace

// docs/method.md §2 "Error estimate": the solvers stop when the estimate of the true error is at
// most the tolerance; the true error there must be at most the tolerance, and the estimate at least
// the true error. At a loose tolerance a strategy that converges within the few periods the estimate
// needs (fas-aposteriori here: true error 1e-4 after 4 relaxations, the first estimate after 6) stops
// further below it.
TEST(Tolerance, BoundsTheTrueErrorOfEveryIterativeStrategy) {
  for (const std::string name : {"latin", "latin-pgd", "fas-aposteriori", "fas-apriori"})
    for (double tolerance : {1e-4, 1e-6}) {
      const auto r = solve(name, tolerance);
      ASSERT_TRUE(r.summary.converged()) << name << ": " << r.summary.message;
      ASSERT_TRUE(r.summary.error.has_value()) << name;
      EXPECT_LE(*r.summary.error, tolerance) << name;
      EXPECT_GE(r.summary.error_estimate, *r.summary.error) << name << " at " << tolerance;
      std::cout << "[ measured ] " << name << " at " << tolerance << ": estimate / true error "
                << r.summary.error_estimate / *r.summary.error << "\n";
    }
}

// The goal of docs/method.md §2: at the default tolerance the estimate is within 10 times the true
// error. LATIN's order-2 extrapolation meets it (ratios 1.5 to 2 here and on every hard case), and
// so does the calibrated indicator of FAS (measured here: 4.0 for fas-aposteriori, 3.6 for
// fas-apriori; 2 to 8 on the hard cases, docs/hard_cases.md).
TEST(Tolerance, EstimateIsWithinTenTimesTheTrueErrorAtTheDefaultTolerance) {
  for (const std::string name : {"latin", "latin-pgd", "fas-aposteriori", "fas-apriori"}) {
    const auto r = solve(name, 1e-6);
    ASSERT_TRUE(r.summary.error.has_value()) << name;
    EXPECT_LE(r.summary.error_estimate, 10 * *r.summary.error) << name;
  }
}

TEST(LatinPgd, ReachesTheIncrementalSolutionWithFewSparseSolves) {
  const auto r = solve("latin-pgd", 1e-8);
  ASSERT_TRUE(r.summary.converged()) << r.summary.message;
  EXPECT_LE(*r.summary.error, 1e-8);
  const auto& last = r.summary.history.back();
  EXPECT_GT(last.rank, 0);
  // A plain LATIN iteration costs m = 41 solves; latin-pgd spends one per direction, at most d n_C.
  EXPECT_LE(last.sparse_solves, 2 * fixture().problem.contact.size() + 2);
  EXPECT_LT(last.sparse_solves, 41L * r.summary.iterations / 4);
}

TEST(FasApriori, ReachesTheIncrementalSolutionWithFewerRelaxationsThanLatin) {
  const auto a = solve("fas-apriori", 1e-8);
  ASSERT_TRUE(a.summary.converged()) << a.summary.message;
  EXPECT_LE(*a.summary.error, 1e-8);
  const auto latin = solve("latin", 1e-8);
  ASSERT_TRUE(latin.summary.converged());
  EXPECT_LT(2 * a.summary.relaxations, latin.summary.relaxations);
}

// At κ = 100 the map from the separated stage's projection error to the fixed point is large: with
// 0.2.0's floor on that error (γ · tolerance · ‖w‖) this scene stopped at true error 1.16e-6 for
// tolerance 1e-6 (measured, 290 relaxations); with the bound γ · gap alone (the default since), at
// 4.7e-7 in 294 (measured on the full-size case kappa_100 of docs/hard_cases.md).
TEST(FasApriori, MeetsTheToleranceAtAnExtremeSearchScale) {
  stc::Scene scene = stc::test::seedScene(51, 101);
  scene.search_direction.scale = 100.0;
  const stc::test::StrategyFixture f(scene);
  const auto r = f.solve("fas-apriori", 1e-6);
  ASSERT_TRUE(r.summary.converged()) << r.summary.message;
  ASSERT_TRUE(r.summary.error.has_value());
  EXPECT_LE(*r.summary.error, 1e-6);
  EXPECT_GE(r.summary.error_estimate, *r.summary.error);
}

TEST(AprioriBasis, AnExpansionThatFitsIsTheWholeCoarseSpace) {
  // With the default 15 + 30 columns, the expansion after one solve holds fewer directions: the
  // coarse space is its whole span (the traces of U_F and of every response), not a few modes.
  const auto& f = fixture();
  stc::pgd::ControlledGlobalStage stage(f.problem, {});
  stc::fas::AprioriBasisProvider provider(stage, {});
  stc::InterfaceHistory s, hat;
  stc::latin::localStage(f.problem.contact, f.incremental.interface, hat);
  stage.solve(hat, s);
  const auto& basis = stage.basis();
  ASSERT_LE(basis.energyFactor().rank(), 45);
  const auto space = provider.coarseSpace(hat);
  EXPECT_EQ(space.rank(), basis.energyFactor().rank());
  Eigen::MatrixXd traces(basis.loadTraces().rows(), basis.loadTraces().cols() + basis.size());
  traces << basis.loadTraces(), basis.traces();
  const Eigen::MatrixXd& T = space.interface();
  const Eigen::MatrixXd rest = traces - T * T.completeOrthogonalDecomposition().solve(traces);
  EXPECT_LE(rest.norm(), 1e-8 * traces.norm());
}

TEST(AprioriBasis, CoarseSpaceIsEnergyOrthonormal) {
  // The provider's coarse space is known by its traces B Y; with Y rebuilt from the same
  // combination the coarse operator Yᵀ A Y must be the identity (seed eq. (8) with R A P = I).
  const auto& f = fixture();
  stc::pgd::ControlledGlobalStage stage(f.problem, {});
  stc::fas::AprioriBasisOptions options;
  options.modes = 3;
  options.increment_modes = 1;
  stc::fas::AprioriBasisProvider provider(stage, options);
  stc::InterfaceHistory s, hat = stc::InterfaceHistory::zeros(f.problem.contact, f.problem.numSteps());
  int larger = 0;  // cycles whose expansion exceeds the coarse space's 4 columns
  for (int cycle = 1; cycle <= 3; ++cycle) {
    stc::InterfaceHistory moved = f.incremental.interface;
    moved.lambda *= cycle / 3.0;  // a moving right-hand side
    stc::latin::localStage(f.problem.contact, moved, hat);
    stage.solve(hat, s);
    const auto space = provider.coarseSpace(hat);
    EXPECT_LE(space.rank(), 4);
    const stc::pgd::EnergySvd svd = stc::pgd::energySvd(stage.basis(), stage.coordinates(), options.modes);
    const Eigen::MatrixXd Y = stc::pgd::spatialModes(stage.basis(), svd.combination);
    EXPECT_LE((Y.transpose() * (stage.matrix() * Y) - Eigen::MatrixXd::Identity(Y.cols(), Y.cols())).cwiseAbs().maxCoeff(),
              1e-8);
    const Eigen::MatrixXd BY = f.problem.contact.B * Y;
    if (stage.basis().energyFactor().rank() <= 4) {
      // The whole expansion fits in 3 + 1 columns: it is the coarse space, which holds its modes.
      EXPECT_EQ(space.rank(), stage.basis().energyFactor().rank()) << "cycle " << cycle;
      const Eigen::MatrixXd& T = space.interface();
      const Eigen::MatrixXd rest = BY - T * T.completeOrthogonalDecomposition().solve(BY);
      EXPECT_LE(rest.norm(), 1e-8 * BY.norm()) << "cycle " << cycle;
      continue;
    }
    ++larger;
    // Its first columns are the leading energy modes of ũ (up to sign): their traces agree.
    for (Eigen::Index j = 0; j < Y.cols(); ++j) {
      const Eigen::VectorXd a = space.interface().col(j), b = BY.col(j);
      EXPECT_NEAR(std::abs(a.dot(b)) / (a.norm() * b.norm()), 1.0, 1e-8) << "cycle " << cycle << ", mode " << j;
    }
  }
  EXPECT_GE(larger, 1);  // the energy-mode branch was exercised
}

TEST(AprioriBasis, TheAnticipatedSpaceHoldsTheDirectionsOfTheNextGlobalStage) {
  // With `anticipate` the coarse space is built from the projection of the next global stage's
  // right-hand side: the directions that stage needs are enriched first and belong to the space
  // (the expansion fits in 15 + 30 columns here), so the space holds the traces of the next
  // solve's displacements; without it they are left for the next relaxation.
  const auto& f = fixture();
  stc::InterfaceHistory first = stc::InterfaceHistory::zeros(f.problem.contact, f.problem.numSteps()), hat, s;
  first.lambda = 0.3 * f.incremental.interface.lambda;
  stc::latin::localStage(f.problem.contact, f.incremental.interface, hat);
  int ranks[2] = {0, 0};
  for (const bool anticipate : {false, true}) {
    stc::pgd::ControlledGlobalStage stage(f.problem, {});
    stc::fas::AprioriBasisOptions options;
    options.anticipate = anticipate;
    stc::fas::AprioriBasisProvider provider(stage, options);
    stage.solve(first, s);
    stage.observeGap(1e-2 * first.lambda.norm());
    const auto space = provider.coarseSpace(hat);
    ranks[anticipate] = space.rank();
    stc::InterfaceHistory next;
    stage.solve(hat, next);  // the next global stage
    const Eigen::MatrixXd& T = space.interface();
    const Eigen::MatrixXd moved = next.v - stage.basis().freeResponse();  // B X c of the next solve
    const double rest = (moved - T * T.completeOrthogonalDecomposition().solve(moved)).norm() / moved.norm();
    if (anticipate) EXPECT_LE(rest, 1e-8);
    else EXPECT_GE(rest, 1e-3);
  }
  EXPECT_GT(ranks[1], ranks[0]);
}
