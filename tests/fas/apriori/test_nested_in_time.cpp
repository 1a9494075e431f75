// Nested iteration in time (fas/apriori/nested_in_time.hpp): `fas-apriori` on a long grid starts
// from its own solution on every q-th instant, and still stops at the tolerance of the whole grid,
// measured against the incremental reference on the whole grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "fixtures/seed_scene.hpp"
#include "stcontact/build_config.hpp"
#include "stcontact/core/interruption.hpp"
#include "stcontact/fas/apriori/nested_in_time.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "strategies/strategy_fixture.hpp"

namespace {

// The seed scene on 401 instants; a sub-grid of 101 instants is every 4th.
const stc::test::StrategyFixture& fixture() {
  static const stc::test::StrategyFixture f(stc::test::seedScene(31, 401));
  return f;
}

stc::SolveResult solveApriori(int nested_instants, const stc::SolveInputs& given = {}, int max_iterations = 0,
                              bool reduce_interface = true, bool on_iterative = false) {
  stc::SolverSpec spec = fixture().scene.solver;
  spec.setTolerance(1e-6);
  spec.fas_apriori.nested.instants = nested_instants;
  spec.fas_apriori.nested.on_iterative = on_iterative;
  spec.fas_apriori.zone.enabled = reduce_interface;
  if (max_iterations > 0) spec.setMaxIterations(max_iterations);
  stc::SolveInputs inputs = given;
  inputs.reference = &fixture().reference;
  return stc::solve(stc::strategyNamed("fas-apriori"), fixture().problem, spec, inputs);
}

bool says(const stc::SolveResult& r, const std::string& words) {
  return r.summary.message.find(words) != std::string::npos;
}

}  // namespace

TEST(NestedInTime, StrideKeepsAtLeastTheSubgridsInstants) {
  EXPECT_EQ(stc::fas::nestedStride(2001, 201), 10);
  EXPECT_EQ(stc::fas::nestedStride(1001, 201), 5);
  EXPECT_EQ(stc::fas::nestedStride(401, 201), 2);
  EXPECT_EQ(stc::fas::nestedStride(400, 201), 0);  // every instant: nothing to nest
  EXPECT_EQ(stc::fas::nestedStride(201, 201), 0);
  EXPECT_EQ(stc::fas::nestedStride(2001, 0), 0);   // off
  EXPECT_EQ(stc::fas::nestedStride(2001, 2), 2000);
}

// The largest stride bounds q, the sub-grid then finer than asked: the default options' sub-grid of
// 10 001 instants is every 10th (1001 instants), of 2001 every 10th as without the bound.
TEST(NestedInTime, StrideStaysWithinItsBound) {
  const stc::fas::NestedInTimeOptions defaults;
  EXPECT_EQ(stc::fas::nestedStride(10001, defaults.instants, defaults.max_stride), 10);
  EXPECT_EQ(stc::fas::nestedStride(2001, defaults.instants, defaults.max_stride), 10);
  EXPECT_EQ(stc::fas::nestedStride(10001, 201, 0), 50);  // no bound
  EXPECT_EQ(stc::fas::nestedStride(2001, 2, 7), 7);
  EXPECT_EQ(stc::fas::nestedStride(401, 201, 10), 2);
  EXPECT_EQ(stc::fas::nestedStride(2001, 0, 10), 0);     // off
}

// The true error on the whole grid is below the tolerance, as without the sub-grid; the first
// record already counts the sub-grid's sparse solves and time (its stage in the summary).
TEST(NestedInTime, StartsFromTheSubgridAndMeetsTheWholeGridsTolerance) {
  const stc::SolveResult nested = solveApriori(101);
  const stc::SolveResult plain = solveApriori(0);
  ASSERT_TRUE(nested.summary.converged()) << nested.summary.message;
  ASSERT_TRUE(plain.summary.converged()) << plain.summary.message;
  EXPECT_TRUE(says(nested, "started from the solve on every 4th instant (101 instants, ")) << nested.summary.message;
  EXPECT_FALSE(says(plain, "every"));
  ASSERT_TRUE(nested.summary.error.has_value());
  EXPECT_LE(*nested.summary.error, 1e-6);
  EXPECT_LE(*plain.summary.error, 1e-6);
  const stc::IterationRecord& first = nested.summary.history.front();
  const auto& stages = nested.summary.stages;
  const auto found = std::find_if(stages.begin(), stages.end(),
                                  [](const stc::SolveStage& s) { return s.kind == stc::SolveStage::Kind::SubGrid; });
  ASSERT_NE(found, stages.end());
  const stc::SolveStage& subgrid = *found;
  EXPECT_GT(subgrid.relaxations, 0);
  EXPECT_GT(subgrid.wall_s, 0.0);
  EXPECT_GE(first.sparse_solves, subgrid.sparse_solves);
  EXPECT_GT(first.wall_s, subgrid.wall_s);
  EXPECT_EQ(first.relaxations, 1);
  // The start is the shape of the solution: the first relaxation is closer to it than the plain
  // solve's first one.
  ASSERT_TRUE(first.error && plain.summary.history.front().error);
  EXPECT_LT(*first.error, 0.1 * *plain.summary.history.front().error);
}

TEST(NestedInTime, AWarmStartTurnsItOff) {
  stc::SolveInputs inputs;
  inputs.start = &fixture().incremental.interface;
  const stc::SolveResult r = solveApriori(101, inputs);
  EXPECT_FALSE(says(r, "every")) << r.summary.message;
}

// On an iterative backend each direction is a Krylov solve and the sub-grid adds directions the
// whole grid would not need (docs/scale.md, "Nested iteration in time on CG + GAMG"): it nests there
// only when asked. Both solves meet the tolerance in true error.
TEST(NestedInTime, AnIterativeBackendNestsOnlyWhenAsked) {
#if !STC_HAVE_PETSC
  GTEST_SKIP() << "an iterative backend needs a build with PETSc";
#else
  stc::LinearSolverOptions linear;
  linear.backend = stc::LinearBackend::CgGamg;
  linear.rtol = 1e-10;
  stc::PreparedOperators operators(linear);
  stc::SolveInputs inputs;
  inputs.operators = &operators;
  const stc::SolveResult plain = solveApriori(101, inputs);
  const stc::SolveResult nested = solveApriori(101, inputs, 0, true, true);
  ASSERT_TRUE(plain.summary.converged()) << plain.summary.message;
  ASSERT_TRUE(nested.summary.converged()) << nested.summary.message;
  EXPECT_FALSE(says(plain, "every")) << plain.summary.message;
  EXPECT_TRUE(says(nested, "started from the solve on every 4th instant")) << nested.summary.message;
  ASSERT_TRUE(plain.summary.error && nested.summary.error);
  EXPECT_LE(*plain.summary.error, 1e-6);
  EXPECT_LE(*nested.summary.error, 1e-6);
#endif
}

// The callback sees the records of the result (all but the one the solve stops on, as without the
// sub-grid): the sub-grid's sparse solves and time included.
TEST(NestedInTime, TheCallbackSeesTheRecordsOfTheResult) {
  std::vector<stc::IterationRecord> seen;
  stc::SolveInputs inputs;
  inputs.callback = [&](const stc::IterationRecord& r) {
    seen.push_back(r);
    return true;
  };
  const stc::SolveResult r = solveApriori(101, inputs);
  ASSERT_FALSE(seen.empty());
  ASSERT_LE(seen.size(), r.summary.history.size());
  for (size_t i = 0; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].sparse_solves, r.summary.history[i].sparse_solves);
    EXPECT_EQ(seen[i].relaxations, r.summary.history[i].relaxations);
    EXPECT_DOUBLE_EQ(seen[i].wall_s, r.summary.history[i].wall_s);
  }
}

// The sub-grid solve's relaxations, which the callback does not see, are told as a phase (here each
// one: interval 0); the solve is the same with them told.
TEST(NestedInTime, TheSubgridsRelaxationsAreToldAsAPhase) {
  std::vector<std::string> lines;
  stc::NotedPhase phase([&](const std::string& line) { lines.push_back(line); }, "on every 4th instant: ", 0.0);
  const stc::IterationCallback progress = stc::fas::subgridProgress(phase);
  stc::IterationRecord r;
  r.relaxations = 12;
  r.error_estimate = 3.1e-3;
  r.sparse_solves = 412;
  EXPECT_TRUE(progress(r));
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].rfind("on every 4th instant: relaxation 12, estimate 3.10e-03, 412 sparse solves, ", 0), 0u)
      << lines[0];
  stc::SolveInputs noted;
  noted.phase_note = [&](const std::string& line) { lines.push_back(line); };
  const stc::SolveResult told = solveApriori(101, noted), silent = solveApriori(101);
  EXPECT_EQ(told.summary.relaxations, silent.summary.relaxations);
  EXPECT_EQ(told.summary.sparseSolves(), silent.summary.sparseSolves());
  EXPECT_TRUE(told.interface.lambda == silent.interface.lambda);
}

// A caller's stop (src/core/interruption.hpp, StopProbe) is heard between the sub-grid's relaxations,
// which make no record of the solve: the solve ends there with stc::Interrupted, before the whole
// grid's first record (the callback is never called). The probe is asked once per sub-grid
// relaxation; it says stop at its third question.
TEST(NestedInTime, ACallersStopIsHeardInTheSubgrid) {
  int asked = 0, records = 0;
  const stc::StopProbe probe([&] { return ++asked < 3; });
  stc::SolveInputs inputs;
  inputs.callback = [&](const stc::IterationRecord&) {
    ++records;
    return true;
  };
  EXPECT_THROW(solveApriori(101, inputs), stc::Interrupted);
  EXPECT_EQ(asked, 3);
  EXPECT_EQ(records, 0);
}

// On every node (no reduced interface, whose later rounds would not nest): 3 relaxations are not
// enough for the sub-grid, and the whole grid starts from s = 0 again.
TEST(NestedInTime, ASubgridSolveThatDoesNotConvergeIsSaid) {
  const stc::SolveResult r = solveApriori(101, {}, 3, false);
  EXPECT_TRUE(says(r, "(101 instants, 3 relaxations, ")) << r.summary.message;
  EXPECT_TRUE(says(r, "did not converge: the whole grid solved from its own start")) << r.summary.message;
  EXPECT_EQ(r.summary.relaxations, 3);
}

// Without the reduced interface the whole interface nests too, and meets the tolerance.
TEST(NestedInTime, NestsOnEveryNodeToo) {
  const stc::SolveResult r = solveApriori(101, {}, 0, false);
  ASSERT_TRUE(r.summary.converged()) << r.summary.message;
  EXPECT_TRUE(says(r, "started from the solve on every 4th instant (101 instants, ")) << r.summary.message;
  ASSERT_TRUE(r.summary.error.has_value());
  EXPECT_LE(*r.summary.error, 1e-6);
}
