// Warm starts through the registry (strategies/registry.hpp) (src/solver/warm_start.hpp): a solve begun from a neighbouring
// friction's solution (and, for the a priori bases, its interface directions) reaches the incremental
// solution of its own friction, in fewer relaxations than from zero; a start of the wrong size is
// refused. Small seed scene (21 contact nodes, 21 instants), as the sweep's command-line test.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <stdexcept>

#include "fixtures/seed_scene.hpp"
#include "stcontact/incremental/condensed_interface.hpp"
#include "stcontact/incremental/error_reference.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/pgd/controlled_global_stage.hpp"
#include "stcontact/strategies/registry.hpp"

namespace {

/// One friction value: its problem, and the true-error measure against its incremental solution.
struct Value {
  explicit Value(double mu) : scene(make(mu)), problem(stc::buildProblem(scene)) {
    const stc::SolveResult incremental = stc::solveIncremental(problem);
    const stc::CholmodFactor K(problem.stiffness_free, "K");
    reference = std::make_unique<stc::ErrorReference>(problem, K, stc::CondensedInterface::build(problem, K).delassus,
                                                      incremental.interface.lambda);
  }
  static stc::Scene make(double mu) {
    stc::Scene scene = stc::test::seedScene(21, 21);
    scene.contact.friction = mu;
    scene.solver.setTolerance(1e-6);
    return scene;
  }
  stc::Scene scene;
  stc::Problem problem;
  std::unique_ptr<stc::ErrorReference> reference;
};

const Value& value(double mu) {
  static std::map<double, std::unique_ptr<Value>> values;
  auto& v = values[mu];
  if (!v) v = std::make_unique<Value>(mu);
  return *v;
}

stc::SolveResult solve(const std::string& solver, const Value& v, const stc::SolveResult* previous = nullptr,
                       bool reduce_interface = true) {
  stc::SolveInputs inputs;
  inputs.reference = v.reference.get();
  if (previous) {
    inputs.start = &previous->interface;
    if (previous->interface_directions.cols() > 0) inputs.basis_seed = &previous->interface_directions;
  }
  stc::SolverSpec spec = v.scene.solver;
  spec.fas_apriori.zone.enabled = reduce_interface;
  return stc::solve(stc::strategyNamed(solver), v.problem, spec, inputs);
}

const std::vector<std::string>& iterativeSolvers() {
  static const std::vector<std::string> names = {"latin", "latin-pgd", "fas-aposteriori", "fas-apriori"};
  return names;
}

}  // namespace

// The solvers stop on an estimate of the true error (src/solver/error_estimate.hpp): at tolerance
// 1e-6 the true error must be at most 1e-6, warm start or not.
constexpr double kAgreement = 1e-6;

TEST(WarmStart, FromANeighbouringFrictionReachesTheIncrementalSolution) {
  for (const std::string& solver : iterativeSolvers()) {
    const stc::SolveResult previous = solve(solver, value(0.15));
    ASSERT_TRUE(previous.summary.converged()) << solver << ": " << previous.summary.message;
    const stc::SolveResult warm = solve(solver, value(0.3), &previous);
    ASSERT_TRUE(warm.summary.converged()) << solver << ": " << warm.summary.message;
    ASSERT_TRUE(warm.summary.error.has_value()) << solver;
    EXPECT_LE(*warm.summary.error, kAgreement) << solver << " (indicator " << warm.summary.indicator << ")";
  }
}

TEST(WarmStart, NeedsFewerRelaxationsThanAColdStartForLatinAndFasApriori) {
  // One step of the sweep 0.05:0.5:10. Not a law for any jump: from 0.15 straight to 0.3, where
  // the stick zone differs more, latin needs 38 relaxations warm against 27 cold (measured).
  for (const std::string solver : {"latin", "fas-apriori"}) {
    const stc::SolveResult previous = solve(solver, value(0.15));
    const stc::SolveResult warm = solve(solver, value(0.2), &previous);
    const stc::SolveResult cold = solve(solver, value(0.2));
    ASSERT_TRUE(cold.summary.converged()) << solver;
    EXPECT_LT(warm.summary.relaxations, cold.summary.relaxations) << solver;
  }
}

TEST(WarmStart, FromItsOwnSolutionStopsSoon) {
  // The converged solution of the same problem is the iteration's fixed point (to the tolerance);
  // the error estimate still needs a few periods to measure the contraction rate (one period: 1
  // relaxation for LATIN, a FAS cycle's 2): its first estimate comes at relaxation 4p + 1 (window
  // of 3 rates, src/solver/error_estimate.hpp). A restart stops within one period of it.
  // Tolerance 1e-8 for the start, well below the 1e-6 asked of the restart.
  for (const std::string& solver : iterativeSolvers()) {
    const Value& v = value(0.15);
    stc::SolverSpec tight = v.scene.solver;
    tight.setTolerance(1e-8);
    const stc::SolveResult converged = stc::solve(stc::strategyNamed(solver), v.problem, tight);
    ASSERT_TRUE(converged.summary.converged()) << solver;
    const stc::SolveResult restart = solve(solver, v, &converged);
    EXPECT_TRUE(restart.summary.converged()) << solver;
    const int period = solver.rfind("fas", 0) == 0 ? 2 : 1;
    EXPECT_LE(restart.summary.relaxations, 5 * period + 1) << solver;
  }
}

TEST(WarmStart, AprioriDirectionsSeedTheNextBasis) {
  for (const std::string solver : {"latin-pgd", "fas-apriori"}) {
    const stc::SolveResult previous = solve(solver, value(0.15));
    ASSERT_GT(previous.interface_directions.cols(), 0) << solver;
    EXPECT_EQ(previous.interface_directions.rows(), 2 * value(0.15).problem.contact.size()) << solver;
    EXPECT_GT(previous.spatial_modes.cols(), 0) << solver;
    EXPECT_EQ(previous.spatial_modes.rows(), value(0.15).problem.numFreeDofs()) << solver;
    const stc::SolveResult warm = solve(solver, value(0.3), &previous);
    EXPECT_EQ(warm.interface_directions.rows(), previous.interface_directions.rows()) << solver;
    // On the whole interface the seeded directions stay (re-orthonormalised, their responses
    // solved): no shrinking. With the reduced interface (fas-apriori's default) they are cut to the
    // new contact zone's rows and may lose some.
    const stc::SolveResult whole = solve(solver, value(0.3), &previous, false);
    EXPECT_GE(whole.interface_directions.cols(), previous.interface_directions.cols()) << solver;
  }
  EXPECT_EQ(solve("latin", value(0.15)).spatial_modes.cols(), 0);
}

// The sparse solves a separated stage spends before its first relaxation, its loads' responses and
// those of a warm start's directions (where the factor does not give their traces), are the solve's
// own: its first record counts what a stage that seeds and then solves once has counted.
TEST(WarmStart, TheFirstRecordCountsTheSolvesSpentBeforeTheIteration) {
  const Value& v = value(0.3);
  const stc::SolveResult previous = solve("latin-pgd", value(0.15));
  stc::SolveInputs inputs;
  inputs.start = &previous.interface;
  inputs.basis_seed = &previous.interface_directions;
  const stc::SolveResult warm = stc::solve(stc::strategyNamed("latin-pgd"), v.problem, v.scene.solver, inputs);
  ASSERT_FALSE(warm.summary.history.empty());

  stc::pgd::ControlledGlobalStage stage(v.problem, v.scene.solver.latin_pgd.stage);
  const long loads = stage.sparseSolves();
  EXPECT_GT(loads, 0);  // the seed scene's prescribed motion has separated load terms
  stage.seed(previous.interface_directions);
  stc::InterfaceHistory hat, s;
  stc::latin::localStage(v.problem.contact, previous.interface, hat);
  stage.solve(hat, s);
  EXPECT_EQ(warm.summary.history.front().sparse_solves, stage.sparseSolves());
}

TEST(WarmStart, AStartOfTheWrongSizeIsRefused) {
  const Value& v = value(0.15);
  const stc::InterfaceHistory wrong = stc::InterfaceHistory::zerosWithRows(v.problem.contact.rows() + 2, v.problem.numSteps());
  const Eigen::MatrixXd wrong_modes = Eigen::MatrixXd::Zero(2 * v.problem.contact.size() + 2, 3);
  for (const std::string& solver : iterativeSolvers()) {
    stc::SolveInputs inputs;
    inputs.start = &wrong;
    EXPECT_THROW(stc::solve(stc::strategyNamed(solver), v.problem, v.scene.solver, inputs), std::invalid_argument) << solver;
  }
  stc::SolveInputs inputs;
  inputs.basis_seed = &wrong_modes;
  EXPECT_THROW(stc::solve(stc::strategyNamed("fas-apriori"), v.problem, v.scene.solver, inputs), std::invalid_argument);
}

// Spatial modes are rebuilt after the last iteration only when asked for: without them the solve is
// the same (iterates, directions, counts), its modes empty.
TEST(WarmStart, SpatialModesOnlyWhenAskedFor) {
  const Value& v = value(0.15);
  for (const std::string solver : {"latin-pgd", "fas-apriori"}) {
    stc::SolveInputs without;
    without.spatial_modes = false;
    const stc::SolveResult bare = stc::solve(stc::strategyNamed(solver), v.problem, v.scene.solver, without);
    const stc::SolveResult full = stc::solve(stc::strategyNamed(solver), v.problem, v.scene.solver);
    EXPECT_EQ(bare.spatial_modes.size(), 0) << solver;
    EXPECT_GT(full.spatial_modes.cols(), 0) << solver;
    EXPECT_EQ(bare.summary.relaxations, full.summary.relaxations) << solver;
    EXPECT_EQ(bare.interface.lambda, full.interface.lambda) << solver;
    EXPECT_EQ(bare.interface_directions, full.interface_directions) << solver;
  }
}
