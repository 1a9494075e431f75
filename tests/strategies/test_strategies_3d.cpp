// Every strategy on the small 3D seed scene (tests/fixtures/hemisphere_scene.hpp), against the
// incremental solver's cone law: the same code above the contact interface as in 2D, only the
// interface has three rows per node. The full-size study is docs/strategies_3d.md.
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/slab_scene.hpp"
#include "stcontact/options/fas_options.hpp"
#include "stcontact/scene/scene.hpp"
#include "stcontact/solver/contact_law_check.hpp"
#include "strategies/strategy_fixture.hpp"

namespace {

const stc::test::StrategyFixture& hemisphere() {
  static const stc::test::StrategyFixture f(stc::test::hemisphereScene(4, 21));
  return f;
}

}  // namespace

// The tolerance bounds the true error (docs/method.md §2) in 3D as in 2D, and the admissible
// iterate satisfies the cone law to the tolerance's order.
TEST(ThreeD, EveryStrategyReachesTheIncrementalSolutionWithinTheTolerance) {
  for (const std::string name : {"latin", "latin-pgd", "fas-aposteriori", "fas-apriori"}) {
    const auto r = hemisphere().solve(name, 1e-6);
    ASSERT_TRUE(r.summary.converged()) << name << ": " << r.summary.message;
    ASSERT_TRUE(r.summary.error.has_value()) << name;
    EXPECT_LE(*r.summary.error, 1e-6) << name;
    EXPECT_GE(r.summary.error_estimate, *r.summary.error) << name;
    EXPECT_LT(stc::checkContactLaw(hemisphere().problem, r.admissible()).max(), 1e-4) << name;
    std::cout << "[ measured ] 3D " << name << ": " << r.summary.relaxations << " relaxations, true error "
              << *r.summary.error << ", estimate / true " << r.summary.error_estimate / *r.summary.error << "\n";
  }
}

// The a priori two-level solver keeps its advantage in relaxations over plain LATIN in 3D.
TEST(ThreeD, FasAprioriNeedsFewerRelaxationsThanLatin) {
  const auto fas = hemisphere().solve("fas-apriori", 1e-6);
  const auto latin = hemisphere().solve("latin", 1e-6);
  ASSERT_TRUE(fas.summary.converged() && latin.summary.converged());
  EXPECT_LT(2 * fas.summary.relaxations, latin.summary.relaxations);
}

// On the 3D hemisphere the coarse corrections of 15 plain restricted LATIN iterations (the seed's
// cycle, strict safeguard θ = 1) overshoot and the safeguard rejects them; with i_C following its
// verdicts (halved on a rejection, one more on an acceptance) fewer are rejected and fewer
// relaxations are needed. Both reach the solution. Measured (relaxations and rejections, adapted
// against fixed, `stcontact solve examples/scenes/hemisphere.toml` with these settings), since the
// separated stage orders the interface last at every size: divisions 7, m = 21 (this test): 23/2
// against 29/4; 6, 21: 21/1 against 21/3 (this test's scene until then, 21/2 against 23/3 before);
// 6, 41 and 7, 41: 15/0 and 23/1 both. Earlier (31/2 against 37/5 at 6, 21 when this test was
// written; before the anticipated expansion 34/2 against 38/4, 30/1 against 33/2 at 6, 41, 40/3
// against 49/6 at 7, 21, 35/2 against 37/3 at 7, 101, whose sanitizer run took 170 s). Not
// everywhere: at 5, 21 the adapted i_C took 37 against 29, at 5, 41 both 22. Without the step of
// the next relaxation in the coarse space (`pgd_step_samples` = 0): with it these long coarse steps
// no longer overshoot on the small hemisphere (next test).
TEST(ThreeD, AdaptedCoarseIterationsSaveRelaxationsWhereCorrectionsOvershoot) {
  stc::Scene scene = stc::test::hemisphereScene(7, 21);
  scene.solver.fas_apriori.fas.coarse_iterations = 15;
  scene.solver.fas_apriori.fas.coarse_anderson = 0;
  scene.solver.fas_apriori.fas.safeguard_growth = 1.0;
  scene.solver.fas_apriori.basis.step_samples = 0;
  const stc::test::StrategyFixture adapted(scene);
  scene.solver.fas_apriori.fas.adapt_coarse_iterations = false;
  const stc::test::StrategyFixture fixed(scene);
  const auto a = adapted.solve("fas-apriori", 1e-6), b = fixed.solve("fas-apriori", 1e-6);
  ASSERT_TRUE(a.summary.converged() && b.summary.converged()) << a.summary.message << " | " << b.summary.message;
  EXPECT_NE(b.summary.message.find("coarse corrections rejected"), std::string::npos) << b.summary.message;
  EXPECT_LT(a.summary.relaxations, b.summary.relaxations);
  EXPECT_LE(*a.summary.error, 1e-6);
  EXPECT_LE(*b.summary.error, 1e-6);
  std::cout << "[ measured ] 3D fas-apriori, i_C adapted: " << a.summary.relaxations << " relaxations ("
            << a.summary.message << "); fixed: " << b.summary.relaxations << " (" << b.summary.message << ")\n";
}

// The step of the next relaxation among the increment modes' sources (AprioriBasisOptions::
// step_samples; docs/method.md §5, "The step of the next relaxation") is the direction the smoother
// moves in now: the same 15 plain coarse iterations at fixed i_C and θ = 1 then overshoot nowhere on
// this hemisphere (14 relaxations, no correction rejected), where without it 3 are rejected and the
// solve takes 23.
TEST(ThreeD, TheStepOfTheNextRelaxationKeepsLongCoarseStepsFromOvershooting) {
  stc::Scene scene = stc::test::hemisphereScene(6, 21);
  scene.solver.fas_apriori.fas.coarse_iterations = 15;
  scene.solver.fas_apriori.fas.coarse_anderson = 0;
  scene.solver.fas_apriori.fas.safeguard_growth = 1.0;
  scene.solver.fas_apriori.fas.adapt_coarse_iterations = false;
  const auto with_step = stc::test::StrategyFixture(scene).solve("fas-apriori", 1e-6);
  scene.solver.fas_apriori.basis.step_samples = 0;
  const auto without = stc::test::StrategyFixture(scene).solve("fas-apriori", 1e-6);
  ASSERT_TRUE(with_step.summary.converged() && without.summary.converged());
  EXPECT_EQ(with_step.summary.message.find("coarse corrections rejected"), std::string::npos)
      << with_step.summary.message;
  EXPECT_NE(without.summary.message.find("coarse corrections rejected"), std::string::npos);
  EXPECT_LT(with_step.summary.relaxations, without.summary.relaxations);
  EXPECT_LE(*with_step.summary.error, 1e-6);
  std::cout << "[ measured ] 3D fas-apriori, i_C = 15 fixed: with the step " << with_step.summary.relaxations
            << " relaxations (" << with_step.summary.message << "); without " << without.summary.relaxations << " ("
            << without.summary.message << ")\n";
}

// In 3D the safeguard's default growth is θ = 1 (fas::defaultSafeguardGrowth; docs/method.md §4): the
// corrections that raise the indicator raise the true error too. A 3D scene without the key solves
// as with θ = 1, and the plane meshes' θ = 1.5 takes a different path here (measured with 3D's
// i_C = 4: 26 relaxations against 27; with i_C = 8, 27 against 29, and 43 at θ = 5).
TEST(ThreeD, TheSafeguardDefaultsToNoGrowth) {
  stc::Scene scene = stc::test::hemisphereScene(6, 21);
  // On the whole interface: on its contact zone this small hemisphere takes 20 relaxations at either
  // θ, and the last assertion, which shows that the default is the one in force, needs a case where
  // θ matters.
  scene.solver.fas_apriori.zone.enabled = false;
  // Without the step of the next relaxation, for the same reason: with it both θ take 18 here.
  scene.solver.fas_apriori.basis.step_samples = 0;
  ASSERT_FALSE(scene.solver.fas_apriori.fas.safeguard_growth);
  const auto by_default = stc::test::StrategyFixture(scene).solve("fas-apriori", 1e-6);
  scene.solver.fas_apriori.fas.safeguard_growth = 1.0;
  const auto strict = stc::test::StrategyFixture(scene).solve("fas-apriori", 1e-6);
  scene.solver.fas_apriori.fas.safeguard_growth = stc::fas::defaultSafeguardGrowth(2, false);
  const auto tolerant = stc::test::StrategyFixture(scene).solve("fas-apriori", 1e-6);
  EXPECT_EQ(by_default.summary.relaxations, strict.summary.relaxations);
  EXPECT_EQ(by_default.summary.message, strict.summary.message);
  EXPECT_NE(tolerant.summary.relaxations, strict.summary.relaxations);
  std::cout << "[ measured ] 3D fas-apriori to 1e-6: theta = 1 " << strict.summary.relaxations
            << " relaxations, theta = " << stc::fas::defaultSafeguardGrowth(2, false) << " (the plane default) "
            << tolerant.summary.relaxations << "\n";
}

// In 3D a coarse step makes at most i_C = 4 coarse iterations by default (fas::defaultCoarseIterations;
// docs/floor.md, "Fewer coarse iterations in 3D"): a 3D scene without the key solves as with
// i_C = 4, and the plane meshes' default of 8 takes a different path here.
TEST(ThreeD, TheCoarseIterationsDefaultToFour) {
  stc::Scene scene = stc::test::hemisphereScene(6, 21);
  ASSERT_FALSE(scene.solver.fas_apriori.fas.coarse_iterations);
  const auto by_default = stc::test::StrategyFixture(scene).solve("fas-apriori", 1e-6);
  scene.solver.fas_apriori.fas.coarse_iterations = 4;
  const auto four = stc::test::StrategyFixture(scene).solve("fas-apriori", 1e-6);
  scene.solver.fas_apriori.fas.coarse_iterations = stc::fas::defaultCoarseIterations(2);
  const auto plane = stc::test::StrategyFixture(scene).solve("fas-apriori", 1e-6);
  ASSERT_TRUE(by_default.summary.converged() && plane.summary.converged());
  EXPECT_EQ(by_default.summary.relaxations, four.summary.relaxations);
  EXPECT_EQ(by_default.summary.message, four.summary.message);
  EXPECT_NE(plane.summary.relaxations, four.summary.relaxations);
  EXPECT_LE(*by_default.summary.error, 1e-6);
  std::cout << "[ measured ] 3D fas-apriori to 1e-6: i_C = 4 " << four.summary.relaxations << " relaxations, i_C = "
            << stc::fas::defaultCoarseIterations(2) << " (the plane default) " << plane.summary.relaxations << "\n";
}

namespace {

const stc::test::StrategyFixture& slab() {
  static const stc::test::StrategyFixture f(stc::test::slabScene(31, 41));
  return f;
}

}  // namespace

// The extruded slab has contact nodes held at u_z = 0 (their τ_2 rows are held rows, B rows empty):
// every strategy still reaches the incremental solution, and no force appears in a held row.
TEST(ThreeD, EveryStrategySolvesTheSlabWithHeldRows) {
  ASSERT_FALSE(slab().problem.contact.held_rows.empty());
  for (const std::string name : {"latin", "latin-pgd", "fas-aposteriori", "fas-apriori"}) {
    const auto r = slab().solve(name, 1e-6);
    ASSERT_TRUE(r.summary.converged()) << name << ": " << r.summary.message;
    ASSERT_TRUE(r.summary.error.has_value()) << name;
    EXPECT_LE(*r.summary.error, 1e-6) << name;
    const Eigen::MatrixXd lambda = r.admissible().lambda;
    double held = 0.0, scale = lambda.cwiseAbs().maxCoeff();
    for (int row : slab().problem.contact.held_rows) held = std::max(held, lambda.row(row).cwiseAbs().maxCoeff());
    EXPECT_LE(held, 1e-12 * scale) << name;
    std::cout << "[ measured ] slab " << name << ": " << r.summary.relaxations << " relaxations, true error "
              << *r.summary.error << ", largest held force / largest force " << held / scale << "\n";
  }
}
