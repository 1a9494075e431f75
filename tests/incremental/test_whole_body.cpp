// The incremental solver's whole-body form (src/incremental/whole_body_newton.hpp): on cg-gamg, the
// same solution as the interface form on CHOLMOD (2D seed scene, 3D half-ball and the fretting
// history's reversals, all with nodes that slip), one solve per active-set iteration; refused clearly where it cannot run.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/contact/contact_state.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/solver/contact_law_check.hpp"

namespace {

using testing::HasSubstr;

// The linear solves' relative residual here: the instants stop at the noise those solves leave in
// the forces (WholeBodyLaw::kNoiseMargin) or at the options' tolerance.
constexpr double kRtol = 1e-12;

stc::SolveResult wholeBody(const stc::Problem& problem, stc::LinearBackend backend = stc::LinearBackend::CgGamg) {
  stc::LinearSolverOptions linear;
  linear.backend = backend;
  linear.rtol = kRtol;
  stc::PreparedOperators operators(linear);
  stc::IncrementalOptions options;
  options.form = stc::IncrementalForm::WholeBody;
  stc::SolveResult result = stc::solveIncremental(problem, options, {.operators = &operators});
  EXPECT_GT(operators.krylovIterations(), 0);
  return result;
}

double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

// Node-instants on the Coulomb cone with a force (|λ_t| ≥ μ λ_n (1 − 1e-8), λ_n > 0) in `lambda`.
int onTheCone(const Eigen::MatrixXd& lambda, int d, double mu) {
  int count = 0;
  for (Eigen::Index k = 0; k < lambda.cols(); ++k)
    for (Eigen::Index i = 0; d * i < lambda.rows(); ++i) {
      const double n = lambda(d * i, k), t = lambda.col(k).segment(d * i + 1, d - 1).norm();
      if (n > 0.0 && t >= mu * n * (1.0 - 1e-8)) ++count;
    }
  return count;
}

// Both forms solve the same discrete law, one to round-off, the other to the noise of its solves at
// a relative residual of 1e-12: a residual r of F moves λ by about r times the conditioning of the
// law's Newton system (of order 10 here); measured 5e-12 (2D) and 9e-12 (3D). 1e-7 leaves room for
// other PETSc builds and is far below any difference of law.
constexpr double kAgreement = 1e-7;

void expectAgreement(const stc::Problem& problem) {
  const stc::SolveResult reference = stc::solveIncremental(problem);
  const stc::SolveResult whole = wholeBody(problem);
  ASSERT_EQ(whole.summary.termination, stc::Termination::Converged) << whole.summary.message;
  EXPECT_GT(onTheCone(reference.interface.lambda, problem.contact.dimension, problem.contact.friction), 0)
      << "the scene must exercise the slipping rows";
  EXPECT_LE(relativeDifference(whole.interface.lambda, reference.interface.lambda), kAgreement);
  EXPECT_LE(relativeDifference(whole.interface.v, reference.interface.v), kAgreement);
  // One solve per iteration, at least one per instant; the message says how many.
  const int solves = whole.summary.sparseSolves();
  EXPECT_GE(solves, problem.numSteps());
  EXPECT_THAT(whole.summary.message, HasSubstr("whole-body form: " + std::to_string(solves) + " sparse solves"));
}

}  // namespace

TEST(WholeBody, AgreesWithTheInterfaceFormOnTheSeedScene) {
  if (!stc::petscBackendsBuilt()) GTEST_SKIP() << "cg-gamg needs PETSc";
  expectAgreement(stc::buildProblem(stc::test::seedScene(31, 41)));
}

TEST(WholeBody, AgreesWithTheInterfaceFormOnTheHalfBall) {
  if (!stc::petscBackendsBuilt()) GTEST_SKIP() << "cg-gamg needs PETSc";
  expectAgreement(stc::buildProblem(stc::test::hemisphereScene(4, 21)));
}

// The fretting history on a coarse grid (201 instants for ten cycles): in gross slip the motion
// reverses within an instant, and the active sets cycled without a line search (instant 149,
// ‖F‖ 0.07 after 50 iterations); backtracking on ‖F‖ takes it through, to the interface form's forces.
TEST(WholeBody, AgreesWithTheInterfaceFormThroughTheFrettingReversals) {
  if (!stc::petscBackendsBuilt()) GTEST_SKIP() << "cg-gamg needs PETSc";
  const stc::Scene scene = stc::readScene(std::filesystem::path(STC_SOURCE_DIR) / "examples/scenes/hemisphere_fretting.toml",
                                          {"mesh.divisions=4", "time.steps=201"});
  expectAgreement(stc::buildProblem(scene));
}

TEST(WholeBody, IsRefusedOnABackendThatCannotHoldDofs) {
  const stc::Problem problem = stc::buildProblem(stc::test::hemisphereScene(3, 5));
  try {
    wholeBody(problem, stc::LinearBackend::Cholmod);
    FAIL() << "no InputError";
  } catch (const stc::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("solver.incremental_form = \"whole-body\": the cholmod backend cannot hold dofs"));
  }
}

TEST(WholeBody, IsRefusedOnAnObstacleWhoseNormalIsNotAnAxis) {
  if (!stc::petscBackendsBuilt()) GTEST_SKIP() << "cg-gamg needs PETSc";
  stc::Scene scene = stc::test::hemisphereScene(3, 5);
  scene.obstacle.normal = Eigen::Vector3d(0.0, 0.6, 0.8);  // touches the sphere at −n, 0.01 away
  scene.obstacle.point = -1.01 * scene.obstacle.normal;
  const stc::Problem problem = stc::buildProblem(scene);
  try {
    wholeBody(problem);
    FAIL() << "no InputError";
  } catch (const stc::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("does not read one free dof of its own"));
  }
}
