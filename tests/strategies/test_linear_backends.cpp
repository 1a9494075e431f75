// Every strategy on every linear backend this build has beside CHOLMOD (mumps and cg-gamg with
// PETSc; src/linalg/spd_solver.hpp), in 2D (the seed scene) and 3D (the hemisphere), at small
// settings, with the true error measured against the incremental solution on CHOLMOD:
//   - "converged" means a true error at most the tolerance, on the iterative backend too (its solves
//     stop at the relative residual 1e-4 τ: docs/method.md §2, "Inexact linear solves"), at the
//     default search direction, and for fas-apriori at both ends of its range (κ = 0.01, 100; latin
//     there stops at its iteration cap, 2000 iterations, 80 s in 3D: the stopping scan's business);
//   - on mumps, a direct factor as CHOLMOD's, the iterations are CHOLMOD's (round-off apart, one
//     either way) and the contact forces agree within the tolerance (measured: 2e-15 for the
//     incremental solver, up to 8e-8 for FAS, whose coarse steps amplify the factors' different
//     round-off);
//   - the incremental solver, without CHOLMOD's trailing block, takes its fallback (solves for the
//     Delassus operator) and agrees with itself on CHOLMOD to 1e-8 (mumps) or τ (cg-gamg).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/io/run_writer.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "strategies/strategy_fixture.hpp"

namespace {

constexpr double kTolerance = 1e-6;

struct BackendCase {
  int dimension;
  std::string strategy;
  stc::LinearBackend backend;
  double search_scale = 4.0;
};

std::string nameOf(const BackendCase& c) {
  std::string name = std::to_string(c.dimension) + "D_" + c.strategy + "_" +
                     (c.backend == stc::LinearBackend::Mumps ? "mumps" : "cggamg") + "_kappa" +
                     std::to_string(c.search_scale);
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

void PrintTo(const BackendCase& c, std::ostream* os) { *os << nameOf(c); }

const stc::test::StrategyFixture& reference(int dimension) { return stc::test::smallFixture(dimension); }

std::vector<BackendCase> backendCases() {
  std::vector<BackendCase> cases;
  if (!stc::petscBackendsBuilt()) return cases;
  for (int dimension : {2, 3})
    for (stc::LinearBackend backend : {stc::LinearBackend::Mumps, stc::LinearBackend::CgGamg}) {
      for (const char* strategy : {"latin", "latin-pgd", "fas-aposteriori", "fas-apriori", "incremental"})
        cases.push_back({dimension, strategy, backend});
      if (backend == stc::LinearBackend::CgGamg)
        for (double kappa : {0.01, 100.0}) cases.push_back({dimension, "fas-apriori", backend, kappa});
    }
  return cases;
}

// The case's scene solved on `backend` (CHOLMOD for the baseline), its true error measured on CHOLMOD.
stc::SolveResult solveOn(const BackendCase& c, stc::LinearBackend backend) {
  const stc::test::StrategyFixture& base = reference(c.dimension);
  stc::Scene scene = base.scene;
  scene.search_direction.scale = c.search_scale;
  scene.solver.setTolerance(kTolerance);
  scene.solver.linear.backend = backend;
  const stc::Problem problem = stc::buildProblem(scene);
  stc::PreparedOperators operators(scene.solver.linearAtTolerance());
  stc::SolveResult result = base.solveAgainstReference(c.strategy, problem, scene.solver, &operators);
  for (const stc::Preparation& p : operators.preparations()) EXPECT_EQ(p.backend, stc::nameOf(backend)) << p.name;
  return result;
}

double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).norm() / std::max(b.norm(), 1e-300);
}

class LinearBackendRun : public ::testing::TestWithParam<BackendCase> {};

TEST_P(LinearBackendRun, ConvergedMeansATrueErrorWithinTheTolerance) {
  const BackendCase& c = GetParam();
  const stc::SolveResult run = solveOn(c, c.backend);
  const stc::SolveSummary& s = run.summary;
  stc::test::printMeasured(nameOf(c), s);
  if (c.strategy == "incremental") {
    const double difference = relativeDifference(run.interface.lambda, reference(c.dimension).incremental.interface.lambda);
    std::cout << "[ measured ] " << nameOf(c) << ": forces against CHOLMOD's " << difference << "\n";
    EXPECT_TRUE(s.converged()) << s.message;
    EXPECT_LE(difference, c.backend == stc::LinearBackend::Mumps ? 1e-8 : kTolerance);
    return;
  }
  ASSERT_TRUE(s.error.has_value());
  if (s.converged()) {
    EXPECT_LE(*s.error, kTolerance) << s.message;
    EXPECT_LE(s.error_estimate, kTolerance);
  }
  if (c.backend != stc::LinearBackend::Mumps) return;
  const stc::SolveResult cholmod = solveOn(c, stc::LinearBackend::Cholmod);
  EXPECT_EQ(s.termination, cholmod.summary.termination);
  EXPECT_NEAR(s.iterations, cholmod.summary.iterations, 1);
  const double difference = relativeDifference(run.interface.lambda, cholmod.interface.lambda);
  std::cout << "[ measured ] " << nameOf(c) << ": forces against CHOLMOD's " << difference << "\n";
  EXPECT_LE(difference, kTolerance);
}

INSTANTIATE_TEST_SUITE_P(EveryStrategy, LinearBackendRun, ::testing::ValuesIn(backendCases()),
                         [](const ::testing::TestParamInfo<BackendCase>& info) { return nameOf(info.param); });
// A build without PETSc has no case to run: the suite is empty there, by design.
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(LinearBackendRun);

}  // namespace

// The separated stage's responses released at once (solver.pgd_response_share = 0) on a backend
// without the trailing block: the same iterates bitwise (the traces are those of the same solves),
// while the spatial modes solve again, and agree with those of the kept responses to the solves'
// round-off; the nodes left out of the zone take their displacement from the traces kept on their
// rows, the same bitwise.
TEST(LinearBackendResponses, ReleasedAtOnceTheIteratesAreTheSame) {
  if (!stc::petscBackendsBuilt()) GTEST_SKIP() << "a build without PETSc: every factor condenses the interface";
  const stc::test::StrategyFixture& base = reference(3);
  stc::SolverSpec kept = base.scene.solver, released = kept;
  kept.setTolerance(kTolerance);
  kept.linear.backend = stc::LinearBackend::Mumps;
  released = kept;
  released.fas_apriori.stage.response_share = 0.0;
  const auto run = [&](const stc::SolverSpec& spec) {
    stc::PreparedOperators operators(spec.linearAtTolerance());
    stc::SolveInputs inputs;
    inputs.operators = &operators;
    inputs.spatial_modes = true;
    return stc::solve(stc::strategyNamed("fas-apriori"), base.problem, spec, inputs);
  };
  const stc::SolveResult a = run(kept), b = run(released);
  ASSERT_TRUE(a.summary.converged()) << a.summary.message;
  EXPECT_EQ(b.summary.iterations, a.summary.iterations);
  EXPECT_EQ(b.summary.error_estimate, a.summary.error_estimate);
  EXPECT_TRUE(b.interface.lambda == a.interface.lambda);
  EXPECT_GT(b.summary.sparseSolves(), a.summary.sparseSolves());
  std::cout << "[ measured ] sparse solves kept " << a.summary.sparseSolves() << ", released "
            << b.summary.sparseSolves() << "\n";
  ASSERT_EQ(b.spatial_modes.cols(), a.spatial_modes.cols());
  EXPECT_LE(relativeDifference(b.spatial_modes, a.spatial_modes), 1e-8);
  EXPECT_TRUE(b.interface.v == a.interface.v);
}

// Without the spatial modes, releasing the responses costs no solve: the lift of the nodes left out
// of the zone (which solved through the rank of the history once X was released) reads the traces
// kept on their rows (ResponseBasis::keepTracesOn), and no phase after the last iteration is told.
TEST(LinearBackendResponses, ReleasedTheLiftOfTheNodesLeftOutSolvesNothing) {
  if (!stc::petscBackendsBuilt()) GTEST_SKIP() << "a build without PETSc: every factor condenses the interface";
  const stc::test::StrategyFixture& base = reference(3);
  stc::SolverSpec kept = base.scene.solver;
  kept.setTolerance(kTolerance);
  kept.linear.backend = stc::LinearBackend::Mumps;
  stc::SolverSpec released = kept;
  released.fas_apriori.stage.response_share = 0.0;
  std::vector<std::string> notes;
  const auto run = [&](const stc::SolverSpec& spec) {
    stc::PreparedOperators operators(spec.linearAtTolerance());
    stc::SolveInputs inputs;
    inputs.operators = &operators;
    inputs.spatial_modes = false;  // as `stcontact solve`: the modes would solve again
    inputs.phase_note = [&](const std::string& line) { notes.push_back(line); };
    return stc::solve(stc::strategyNamed("fas-apriori"), base.problem, spec, inputs);
  };
  const stc::SolveResult a = run(kept), b = run(released);
  EXPECT_TRUE(notes.empty()) << notes.front();  // no phase that cannot solve is announced
  ASSERT_TRUE(a.summary.converged()) << a.summary.message;
  // Solved on a zone: some nodes are left out and lifted.
  const auto zone = std::find_if(b.summary.stages.begin(), b.summary.stages.end(),
                                 [](const stc::SolveStage& s) { return s.kind == stc::SolveStage::Kind::ContactZone; });
  ASSERT_NE(zone, b.summary.stages.end()) << b.summary.message;
  ASSERT_LT(zone->nodes, base.problem.contact.size());
  EXPECT_EQ(b.summary.sparseSolves(), a.summary.sparseSolves());
  EXPECT_TRUE(b.interface.v == a.interface.v);
}

// Inexact directions (pgd/controlled_global_stage.hpp): on cg-gamg the separated stage's directions
// of small weight are solved to a looser residual. fas-apriori in 3D with them (the default cap) and
// without (cap 1): fewer Krylov iterations, the same relaxations, and converged with a true error
// within τ both; their contact forces agree within τ.
namespace {

// The tests' 3D scene's solver at the tolerance on cg-gamg.
stc::SolverSpec cgGamgSpec() {
  stc::SolverSpec spec = reference(3).scene.solver;
  spec.setTolerance(kTolerance);
  spec.linear.backend = stc::LinearBackend::CgGamg;
  return spec;
}

}  // namespace

TEST(LinearBackendInexactDirections, FewerKrylovIterationsTheSameTrueErrorBound) {
  if (!stc::petscBackendsBuilt()) GTEST_SKIP() << "a build without PETSc has no iterative backend";
  const stc::test::StrategyFixture& base = reference(3);
  const stc::SolverSpec loosened = cgGamgSpec();
  stc::SolverSpec tight = loosened;
  tight.fas_apriori.stage.loosening_cap = 1.0;
  const auto run = [&](const stc::SolverSpec& spec) {
    stc::PreparedOperators operators(spec.linearAtTolerance());
    return base.solveAgainstReference("fas-apriori", base.problem, spec, &operators);
  };
  const stc::SolveResult a = run(loosened), b = run(tight);
  std::cout << "[ measured ] Krylov iterations with loosened directions " << a.summary.krylov_iterations
            << ", without " << b.summary.krylov_iterations << "; true errors " << a.summary.error.value_or(-1.0)
            << ", " << b.summary.error.value_or(-1.0) << "\n";
  for (const stc::SolveResult* r : {&a, &b}) {
    ASSERT_TRUE(r->summary.converged()) << r->summary.message;
    ASSERT_TRUE(r->summary.error.has_value());
    EXPECT_LE(*r->summary.error, kTolerance);
  }
  EXPECT_LT(a.summary.krylov_iterations, b.summary.krylov_iterations);
  EXPECT_EQ(a.summary.iterations, b.summary.iterations);
  EXPECT_LE(relativeDifference(a.interface.lambda, b.interface.lambda), kTolerance);
}

// The same on cg-gamg, where the spatial modes solve through the rank of the history with their
// small modes loosened (pgd/response_basis.hpp, liftedModes) and the nodes left out read the traces
// kept on their rows: the same iterates, and the interface histories, far nodes included, within
// 1e-7 of those of the kept responses (measured 0). What follows the last iteration is told through
// phase_note (two lines; none where the responses were kept: no solve), and the last record counts
// its Krylov iterations as the summary does.
TEST(LinearBackendResponses, ReleasedOnCgGamgTheLiftAgreesWithTheKeptResponses) {
  if (!stc::petscBackendsBuilt()) GTEST_SKIP() << "a build without PETSc has no iterative backend";
  const stc::SolverSpec kept = cgGamgSpec();
  stc::SolverSpec released = kept;
  released.fas_apriori.stage.response_share = 0.0;
  std::vector<std::string> notes;
  const auto run = [&](const stc::SolverSpec& spec) {
    notes.clear();
    stc::PreparedOperators operators(spec.linearAtTolerance());
    stc::SolveInputs inputs{.operators = &operators};
    inputs.phase_note = [&](const std::string& line) { notes.push_back(line); };
    return stc::solve(stc::strategyNamed("fas-apriori"), reference(3).problem, spec, inputs);
  };
  const stc::SolveResult a = run(kept);
  EXPECT_TRUE(notes.empty()) << notes.front();
  const stc::SolveResult b = run(released);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_NE(notes[0].find("at most"), std::string::npos) << notes[0];
  EXPECT_NE(notes[1].find("sparse solves"), std::string::npos) << notes[1];
  ASSERT_TRUE(a.summary.converged()) << a.summary.message;
  ASSERT_GE(b.summary.history.size(), 2u);
  EXPECT_EQ(b.summary.history.back().krylov_iterations, b.summary.krylov_iterations);
  EXPECT_EQ(b.summary.iterations, a.summary.iterations);
  EXPECT_GT(b.summary.sparseSolves(), a.summary.sparseSolves());
  const double difference = relativeDifference(b.interface.v, a.interface.v);
  std::cout << "[ measured ] cg-gamg, released against kept: sparse solves " << b.summary.sparseSolves() << " against "
            << a.summary.sparseSolves() << ", interface v " << difference << "\n";
  EXPECT_LE(difference, 1e-7);
  EXPECT_LE(relativeDifference(b.interface.lambda, a.interface.lambda), 1e-7);
}

// A Krylov solve that reaches its cap ends the run as a numerical issue naming the backend and
// PETSc's reason, with zero fields: never a wrong answer, never an internal failure.
TEST(LinearBackendFailure, EndsTheRunAsANumericalIssueNamingTheBackend) {
  if (!stc::petscBackendsBuilt()) GTEST_SKIP() << "a build without PETSc has no iterative backend";
  stc::Scene scene = stc::test::seedScene(21, 11);
  scene.solver.linear.backend = stc::LinearBackend::CgGamg;
  scene.solver.linear.max_iterations = 2;
  const stc::Problem problem = stc::buildProblem(scene);
  stc::PreparedOperators operators(scene.solver.linearAtTolerance());
  for (const char* strategy : {"fas-apriori", "latin", "incremental"}) {
    const stc::SolveResult r =
        stc::solve(stc::strategyNamed(strategy), problem, scene.solver, {.operators = &operators});
    EXPECT_EQ(r.summary.termination, stc::Termination::NumericalIssue) << strategy;
    EXPECT_NE(r.summary.message.find("cg-gamg"), std::string::npos) << r.summary.message;
    EXPECT_NE(r.summary.message.find("DIVERGED_ITS"), std::string::npos) << r.summary.message;
    EXPECT_EQ(r.interface.lambda.norm(), 0.0) << strategy;
  }
}

// What an iterative backend spent reaches summary.json: each cg-gamg operator's Krylov solves and
// iterations, and the solve's total (zero where every operator is direct); and so does the
// process's peak resident memory, one entry per rank. A solve given no operators prepares its own
// on the scene's backend.
TEST(LinearBackendCounts, KrylovIterationsAndPeakMemoryReachTheSummary) {
  for (stc::LinearBackend backend : {stc::LinearBackend::Cholmod, stc::LinearBackend::CgGamg}) {
    if (backend != stc::LinearBackend::Cholmod && !stc::petscBackendsBuilt()) continue;
    stc::Scene scene = stc::test::seedScene(21, 11);
    scene.solver.linear.backend = backend;
    const stc::Problem problem = stc::buildProblem(scene);
    stc::PreparedOperators operators(scene.solver.linearAtTolerance());
    const stc::SolveResult r =
        stc::solve(stc::strategyNamed("fas-apriori"), problem, scene.solver, {.operators = &operators});
    ASSERT_TRUE(r.summary.converged()) << r.summary.message;
    const stc::SolveResult alone = stc::solve(stc::strategyNamed("fas-apriori"), problem, scene.solver);
    EXPECT_EQ(alone.summary.krylov_iterations, r.summary.krylov_iterations);  // the same solves, its own operators
    long long solves = 0, iterations = 0;
    for (const stc::Preparation& p : operators.preparations()) {
      EXPECT_EQ(p.iterative, backend == stc::LinearBackend::CgGamg) << p.name;
      solves += p.krylov.solves;
      iterations += p.krylov.iterations;
      if (p.krylov.solves > 0) EXPECT_LE(p.krylov.max_iterations, scene.solver.linear.max_iterations);
    }
    if (backend == stc::LinearBackend::CgGamg) {
      EXPECT_GE(solves, r.summary.sparseSolves());  // every column the stage solved was a Krylov solve
      EXPECT_GT(iterations, solves);                // a relative residual of 1e-10 takes more than one
    } else {
      EXPECT_EQ(solves + iterations, 0);
    }
    // history.csv's column: the solve's count so far, never decreasing, within the summary's total
    // (the lift after the last iteration solves too), and counting on the iterative backend.
    const std::vector<stc::IterationRecord>& h = r.summary.history;
    for (std::size_t i = 1; i < h.size(); ++i) EXPECT_LE(h[i - 1].krylov_iterations, h[i].krylov_iterations);
    EXPECT_LE(h.back().krylov_iterations, r.summary.krylov_iterations);
    EXPECT_EQ(h.back().krylov_iterations > 0, backend == stc::LinearBackend::CgGamg);
    const nlohmann::json json =
        nlohmann::json::parse(stc::summaryJson(problem, r.summary, {"{}", "test", {}, {}, {}}, operators.preparations()));
    EXPECT_EQ(r.summary.krylov_iterations, iterations);  // the solve's: no other user of the operators
    EXPECT_EQ(json.at("krylov_iterations").get<long long>(), iterations);
    ASSERT_EQ(json.at("peak_memory_bytes_per_rank").size(), 1u);
    EXPECT_GT(json.at("peak_memory_bytes").get<double>(), 1e6);  // the libraries alone hold more
    EXPECT_EQ(json.at("peak_memory_bytes").get<double>(), json.at("peak_memory_bytes_per_rank")[0].get<double>());
    // The incremental solver's records (one per instant) count the same way.
    const stc::SolveResult marched = stc::solve(stc::strategyNamed("incremental"), problem, scene.solver);
    const std::vector<stc::IterationRecord>& instants = marched.summary.history;
    ASSERT_FALSE(instants.empty());
    for (std::size_t i = 1; i < instants.size(); ++i)
      EXPECT_LE(instants[i - 1].krylov_iterations, instants[i].krylov_iterations);
    EXPECT_EQ(instants.back().krylov_iterations, marched.summary.krylov_iterations);
    EXPECT_EQ(marched.summary.krylov_iterations > 0, backend == stc::LinearBackend::CgGamg);
  }
}
