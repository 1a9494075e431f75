// solver.incremental_form = "auto" (src/incremental/form_choice.hpp): the whole-body form on a
// backend that holds dofs where the instants are fewer than the interface form's column solves
// (m < d |Z|), the interface form elsewhere; the choice and its reason in the summary, and the run
// solved in the form chosen; the whole-body march turning to the interface form when its measured
// cost per instant says so (src/incremental/form_switch.hpp).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <numeric>

#include "fixtures/hemisphere_scene.hpp"
#include "stcontact/incremental/form_choice.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/incremental/reach_zone.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace {

using testing::HasSubstr;

stc::LinearSolverOptions on(stc::LinearBackend backend) {
  stc::LinearSolverOptions linear;
  linear.backend = backend;
  linear.rtol = 1e-12;
  return linear;
}

// A solve of `problem` on CG + GAMG in `form`, with its operators' Krylov iterations.
struct CgGamgSolve {
  stc::SolveResult result;
  long long krylov = 0;
};
CgGamgSolve onCgGamg(const stc::Problem& problem, stc::IncrementalForm form) {
  stc::IncrementalOptions options;
  options.form = form;
  stc::PreparedOperators operators(on(stc::LinearBackend::CgGamg));
  stc::SolveResult result = stc::solveIncremental(problem, options, {.operators = &operators});
  return {std::move(result), operators.krylovIterations()};
}

// The forms agree to the noise of solves at a relative residual of 1e-12 (test_whole_body.cpp).
void expectTheSameForces(const stc::SolveResult& a, const stc::SolveResult& b) {
  const double scale = b.interface.lambda.cwiseAbs().maxCoeff();
  EXPECT_LE((a.interface.lambda - b.interface.lambda).cwiseAbs().maxCoeff(), 1e-7 * scale);
}

std::vector<int> firstNodes(int count) {
  std::vector<int> zone(static_cast<std::size_t>(count));
  std::iota(zone.begin(), zone.end(), 0);
  return zone;
}

}  // namespace

TEST(IncrementalFormChoice, IsTheWholeBodyFormExactlyWhereTheInstantsAreFewerThanTheColumnSolves) {
  if (!stc::petscBackendsBuilt()) GTEST_SKIP() << "cg-gamg needs PETSc";
  const stc::Problem problem = stc::buildProblem(stc::test::hemisphereScene(3, 21));
  stc::PreparedOperators operators(on(stc::LinearBackend::CgGamg));
  const stc::SpdSolver& stiffness = *operators.stiffnessFree(problem);
  // d |Z| = 3 · 7 = 21 column solves: not more than the 21 instants; 3 · 8 = 24 are.
  const stc::FormChoice level = chooseIncrementalForm(stc::IncrementalForm::Auto, problem, stiffness, firstNodes(7));
  EXPECT_EQ(level.form, stc::IncrementalForm::Interface);
  EXPECT_THAT(level.reason, HasSubstr("interface; 21 instants"));
  EXPECT_THAT(level.reason, HasSubstr("against 21 column solves for the 7 nodes within reach"));
  const stc::FormChoice more = chooseIncrementalForm(stc::IncrementalForm::Auto, problem, stiffness, firstNodes(8));
  EXPECT_EQ(more.form, stc::IncrementalForm::WholeBody);
  EXPECT_THAT(more.reason, HasSubstr("incremental form (auto): whole-body; 21 instants"));
  // No zone: nothing says what the interface form would pay.
  const stc::FormChoice none = chooseIncrementalForm(stc::IncrementalForm::Auto, problem, stiffness, std::nullopt);
  EXPECT_EQ(none.form, stc::IncrementalForm::Interface);
  EXPECT_THAT(none.reason, HasSubstr("no zone within reach"));
  // A form asked for is the form run, with no reason.
  const stc::FormChoice asked = chooseIncrementalForm(stc::IncrementalForm::Interface, problem, stiffness, firstNodes(8));
  EXPECT_EQ(asked.form, stc::IncrementalForm::Interface);
  EXPECT_TRUE(asked.reason.empty()) << asked.reason;
}

TEST(IncrementalFormChoice, IsTheInterfaceFormWhereTheWholeBodyFormCannotRun) {
  const stc::Problem problem = stc::buildProblem(stc::test::hemisphereScene(3, 5));
  stc::PreparedOperators cholmod(on(stc::LinearBackend::Cholmod));
  const stc::FormChoice direct =
      chooseIncrementalForm(stc::IncrementalForm::Auto, problem, *cholmod.stiffnessFree(problem), firstNodes(30));
  EXPECT_EQ(direct.form, stc::IncrementalForm::Interface);
  EXPECT_TRUE(direct.reason.empty()) << "the only form on a backend that cannot hold dofs, nothing weighed: "
                                      << direct.reason;
  if (!stc::petscBackendsBuilt()) GTEST_SKIP() << "cg-gamg needs PETSc";
  stc::Scene tilted = stc::test::hemisphereScene(3, 5);
  tilted.obstacle.normal = Eigen::Vector3d(0.0, 0.6, 0.8);  // rows that read several dofs
  tilted.obstacle.point = -1.01 * tilted.obstacle.normal;
  const stc::Problem slanted = stc::buildProblem(tilted);
  stc::PreparedOperators gamg(on(stc::LinearBackend::CgGamg));
  const stc::FormChoice refused =
      chooseIncrementalForm(stc::IncrementalForm::Auto, slanted, *gamg.stiffnessFree(slanted), firstNodes(30));
  EXPECT_EQ(refused.form, stc::IncrementalForm::Interface);
  EXPECT_THAT(refused.reason, HasSubstr("the whole-body form cannot run: contact row"));
}

TEST(IncrementalFormChoice, AutoSolvesInTheFormItChoseAndSaysWhy) {
  if (!stc::petscBackendsBuilt()) GTEST_SKIP() << "cg-gamg needs PETSc";
  const stc::Problem problem = stc::buildProblem(stc::test::hemisphereScene(4, 21));
  const std::optional<std::vector<int>> zone = stc::reachZone(problem);
  ASSERT_TRUE(zone.has_value());
  ASSERT_GT(3 * static_cast<int>(zone->size()), problem.numSteps()) << "the scene must favour the whole-body form";
  const stc::SolveResult chosen = onCgGamg(problem, stc::IncrementalForm::Auto).result;
  ASSERT_EQ(chosen.summary.termination, stc::Termination::Converged) << chosen.summary.message;
  EXPECT_THAT(chosen.summary.message, HasSubstr("incremental form (auto): whole-body"));
  EXPECT_THAT(chosen.summary.message, HasSubstr("whole-body form: "));
  EXPECT_EQ(chosen.summary.incremental_form, "whole-body");
  // The same instants in the interface form, asked for, on the same backend: the same solution.
  const stc::SolveResult asked = onCgGamg(problem, stc::IncrementalForm::Interface).result;
  EXPECT_EQ(asked.summary.message.find("incremental form (auto)"), std::string::npos) << asked.summary.message;
  EXPECT_EQ(asked.summary.message.find("whole-body form: "), std::string::npos) << asked.summary.message;
  EXPECT_EQ(asked.summary.incremental_form, "interface");
  expectTheSameForces(chosen, asked);
}

TEST(IncrementalFormChoice, AutoOnCholmodIsTheInterfaceFormBitForBit) {
  const stc::Problem problem = stc::buildProblem(stc::test::hemisphereScene(3, 7));
  stc::IncrementalOptions interface;
  interface.form = stc::IncrementalForm::Interface;
  const stc::SolveResult chosen = stc::solveIncremental(problem);
  const stc::SolveResult asked = stc::solveIncremental(problem, interface);
  EXPECT_EQ(chosen.interface.lambda, asked.interface.lambda);
  EXPECT_EQ(chosen.summary.message, asked.summary.message);
  EXPECT_EQ(chosen.summary.incremental_form, "interface");
}

TEST(IncrementalFormChoice, WeighsTheWholeBodyRateOverTheInstantsLeftAgainstTheColumns) {
  // 8 instants in 24 solves of 40 Krylov iterations: 3 solves an instant.
  const stc::MarchCost cost{stc::kInstantsBeforeWeighing, 24, 960};
  // 100 instants left: 300 solves of 40 against 299 columns weighed as solves, then 301.
  EXPECT_TRUE(stc::interfaceIsCheaper(100, 200, 299, cost, std::nullopt));
  EXPECT_FALSE(stc::interfaceIsCheaper(100, 200, 301, cost, std::nullopt));
  // Columns of 26 Krylov iterations: 300 · 40 = 12 000 against 461 · 26 = 11 986, then 462 · 26 = 12 012.
  EXPECT_TRUE(stc::interfaceIsCheaper(100, 200, 461, cost, 26.0));
  EXPECT_FALSE(stc::interfaceIsCheaper(100, 200, 462, cost, 26.0));
  // Not before kInstantsBeforeWeighing instants, nor without a solve.
  EXPECT_FALSE(stc::interfaceIsCheaper(7, 200, 1, {7, 21, 840}, std::nullopt));
  EXPECT_FALSE(stc::interfaceIsCheaper(100, 200, 1, {10, 0, 0}, std::nullopt));
}

// The fretting history's ten cycles on 21 instants (divisions 4): "auto" chooses the whole-body form
// on the assumed solve an instant (21 < d |Z| = 27), but the motion reversing every other instant
// makes it pay 3 (24 solves in the first 8 instants); the march turns to the interface form and
// solves what the interface form solves.
TEST(IncrementalFormChoice, AutoTurnsToTheInterfaceFormWhereTheWholeBodyFormPaysMoreAnInstant) {
  if (!stc::petscBackendsBuilt()) GTEST_SKIP() << "cg-gamg needs PETSc";
  const stc::Scene scene = stc::readScene(std::filesystem::path(STC_SOURCE_DIR) / "examples/scenes/hemisphere_fretting.toml",
                                          {"mesh.divisions=4", "time.steps=21"});
  const stc::Problem problem = stc::buildProblem(scene);
  const std::optional<std::vector<int>> zone = stc::reachZone(problem);
  ASSERT_TRUE(zone.has_value());
  ASSERT_GT(3 * static_cast<int>(zone->size()), problem.numSteps()) << "the rule must choose the whole-body form";
  const CgGamgSolve auto_form = onCgGamg(problem, stc::IncrementalForm::Auto);
  const stc::SolveResult& chosen = auto_form.result;
  ASSERT_EQ(chosen.summary.termination, stc::Termination::Converged) << chosen.summary.message;
  EXPECT_THAT(chosen.summary.message, HasSubstr("incremental form (auto): whole-body"));
  EXPECT_THAT(chosen.summary.message, HasSubstr("whole-body form for the first " +
                                                std::to_string(stc::kInstantsBeforeWeighing) + " instants"));
  EXPECT_THAT(chosen.summary.message, HasSubstr("then the interface form"));
  // The interface form's remarks, as where it is chosen before the march.
  EXPECT_THAT(chosen.summary.message, HasSubstr("Newton systems: "));
  EXPECT_THAT(chosen.summary.message, HasSubstr("Delassus columns of " + std::to_string(zone->size()) + " of " +
                                                std::to_string(problem.contact.size()) + " contact nodes"));
  EXPECT_EQ(chosen.summary.incremental_form, "interface");
  // Fewer Krylov iterations and solves than the whole-body form throughout; the interface form's forces.
  const CgGamgSolve whole = onCgGamg(problem, stc::IncrementalForm::WholeBody);
  EXPECT_LT(auto_form.krylov, whole.krylov);
  EXPECT_LT(chosen.summary.sparseSolves(), whole.result.summary.sparseSolves());
  expectTheSameForces(chosen, onCgGamg(problem, stc::IncrementalForm::Interface).result);
}
