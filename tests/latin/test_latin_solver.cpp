// LATIN global stage and solver: equilibrium of every global-stage result, convergence, agreement
// with the incremental solver on small settings, options and termination statuses.
#include <gtest/gtest.h>

#include "fixtures/seed_scene.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/incremental/condensed_interface.hpp"
#include "stcontact/incremental/error_reference.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/latin/global_stage.hpp"
#include "stcontact/latin/indicator.hpp"
#include "stcontact/latin/latin_solver.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/operators/displacement.hpp"

namespace {

stc::Problem smallSeed(double kappa = 3.0) {
  stc::Scene scene = stc::test::seedScene(31, 41);
  scene.search_direction.scale = kappa;
  return stc::buildProblem(scene);
}

}  // namespace

TEST(GlobalStage, ResultIsInEquilibriumAndOnTheSearchDirection) {
  const stc::Problem problem = smallSeed();
  stc::latin::GlobalStage global(problem, 7);  // a block size that does not divide m
  auto hat = stc::InterfaceHistory::zeros(problem.contact, problem.numSteps());
  hat.lambda.setConstant(0.3);
  hat.v.setConstant(-0.002);
  stc::InterfaceHistory s;
  global.solve(hat, s);
  const Eigen::VectorXd& k = problem.contact.search_direction;
  EXPECT_LE((s.lambda - hat.lambda + k.asDiagonal() * (s.v - hat.v)).cwiseAbs().maxCoeff(), 1e-12);
  // K_ff u = f + Bᵀλ with u = (K + BᵀkB)⁻¹(f + Bᵀ(λ̂ + k v̂)), and v = B u.
  const stc::CholmodFactor K(problem.stiffness_free, "K");
  const Eigen::MatrixXd u = stc::freeDisplacements(problem, K, s.lambda);
  EXPECT_LE((problem.contact.B * u - s.v).cwiseAbs().maxCoeff(), 1e-12 * s.v.cwiseAbs().maxCoeff());
  EXPECT_EQ(global.sparseSolves(), problem.numSteps());
}

TEST(Indicator, VanishesOnlyWhenBothStatesAgree) {
  const Eigen::VectorXd k = Eigen::VectorXd::Constant(4, 2.0);
  stc::InterfaceHistory a{Eigen::MatrixXd::Random(4, 3), Eigen::MatrixXd::Random(4, 3)};
  EXPECT_EQ(stc::latin::indicator(k, a, a), 0.0);
  stc::InterfaceHistory b = a;
  b.lambda(2, 1) += 0.1;
  EXPECT_GT(stc::latin::indicator(k, a, b), 0.0);
  // Homogeneous of degree 0: scaling both states changes nothing.
  stc::InterfaceHistory a2{3 * a.v, 3 * a.lambda}, b2{3 * b.v, 3 * b.lambda};
  EXPECT_NEAR(stc::latin::indicator(k, a2, b2), stc::latin::indicator(k, a, b), 1e-14);
}

TEST(LatinSolver, ConvergesToTheIncrementalSolution) {
  const stc::Problem problem = smallSeed();
  const stc::SolveResult ref = stc::solveIncremental(problem);
  const stc::CholmodFactor K(problem.stiffness_free, "K");
  const stc::ErrorReference reference(problem, K, stc::CondensedInterface::build(problem, K).delassus,
                                      ref.interface.lambda);
  stc::latin::LatinOptions options;
  options.stop.tolerance = 1e-8;
  const stc::SolveResult result = stc::latin::solveLatin(problem, options, {.reference = &reference});
  ASSERT_TRUE(result.summary.converged()) << result.summary.message;
  // LATIN converges linearly; on these small settings the true energy error stays below the
  // indicator (measured ratio ~0.2–0.5), so 1e-8 on η bounds the error well under 1e-7.
  ASSERT_TRUE(result.summary.error.has_value());
  EXPECT_LE(*result.summary.error, 1e-7);
  // The history's true error decreases overall: last well below first.
  EXPECT_LT(*result.summary.history.back().error, 1e-6 * *result.summary.history.front().error);
}

TEST(LatinSolver, RelaxationStillConverges) {
  const stc::Problem problem = smallSeed();
  stc::latin::LatinOptions options;
  options.stop.tolerance = 1e-6;
  options.relaxation = 0.7;
  const stc::SolveResult result = stc::latin::solveLatin(problem, options);
  EXPECT_TRUE(result.summary.converged()) << result.summary.message;
}

TEST(LatinSolver, IterationCountIsDeterministic) {
  const stc::Problem problem = smallSeed();
  stc::latin::LatinOptions options;
  options.stop.tolerance = 1e-6;
  const int first = stc::latin::solveLatin(problem, options).summary.iterations;
  EXPECT_EQ(stc::latin::solveLatin(problem, options).summary.iterations, first);
}

TEST(LatinSolver, CallbackCanStopTheSolve) {
  const stc::Problem problem = smallSeed();
  const auto result = stc::latin::solveLatin(
      problem, {}, {.callback = [](const stc::IterationRecord& r) { return r.iteration < 5; }});
  EXPECT_EQ(result.summary.termination, stc::Termination::StoppedByCallback);
  EXPECT_EQ(result.summary.iterations, 5);
}

TEST(LatinSolver, IterationLimitIsAStatusNotAnError) {
  const stc::Problem problem = smallSeed();
  stc::latin::LatinOptions options;
  options.stop.max_iterations = 3;
  const auto result = stc::latin::solveLatin(problem, options);
  EXPECT_EQ(result.summary.termination, stc::Termination::MaxIterations);
  EXPECT_EQ(result.summary.history.size(), 3u);
  EXPECT_EQ(result.summary.relaxations, 3);
}

TEST(LatinOptions, ValidateNamesTheField) {
  stc::latin::LatinOptions options;
  options.relaxation = 1.5;
  try {
    options.validate();
    FAIL() << "relaxation 1.5 accepted";
  } catch (const stc::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("relaxation"), std::string::npos);
  }
  options = {};
  options.stop.tolerance = 0.0;
  EXPECT_THROW(options.validate(), stc::InputError);
}
