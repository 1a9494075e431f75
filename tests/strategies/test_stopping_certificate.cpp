// Three ways a solve used to report a wrong status at the ends of what users give (docs/method.md §2,
// "Stopping"):
//   - a relaxation ω of 1e-12, in its documented range (0, 1], made steps of ω times the map's own,
//     which the estimate read as a fixed point to round-off: "converged" after 2 or 3 iterations at
//     a true error of 1.7 to 3.4. The fixed point is judged on the map's own step now, and such a
//     run ends on its iteration cap;
//   - a solution that stores no strain energy with the body touching the obstacle (nothing moves,
//     or the body is lifted away and brought back): the indicator is 0 or rounding, the iterate is
//     LATIN's fixed point, hence the solution, and every strategy reports it converged instead of
//     "stagnated";
//   - `latin-pgd` with a large share of the gap left to its separated stage (solver.pgd_gap_share =
//     0.9, in its range (0, 1)) stopped at a true error of 1.2e-6 against τ = 1e-6 on the
//     hemisphere: its iterates lie up to ½ ‖r‖_{k⁻¹} from the exact stage's, which the estimate now
//     adds (latin/linear_stage.hpp).
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/solver/iteration_monitor.hpp"
#include "strategies/strategy_fixture.hpp"

namespace {

constexpr double kTolerance = 1e-6;
const char* const kIterative[] = {"latin", "latin-pgd", "fas-aposteriori", "fas-apriori"};

TEST(TinyRelaxation, NeverPassesForAFixedPoint) {
  for (int dimension : {2, 3}) {
    stc::Scene scene = dimension == 3 ? stc::test::hemisphereScene(4, 11) : stc::test::seedScene(21, 11);
    const stc::test::StrategyFixture fixture(scene);
    for (const char* strategy : {"latin", "latin-pgd"})
      for (double omega : {1e-300, 1e-12, 1e-6}) {
        stc::SolverSpec spec = scene.solver;
        spec.latin.relaxation = spec.latin_pgd.latin.relaxation = omega;
        spec.setTolerance(kTolerance);
        spec.setMaxIterations(40);
        stc::SolveInputs inputs;
        inputs.reference = &fixture.reference;
        const stc::SolveSummary s = stc::solve(stc::strategyNamed(strategy), fixture.problem, spec, inputs).summary;
        const std::string label = std::to_string(dimension) + "D " + strategy + " omega " + std::to_string(omega);
        std::cout << "[ measured ] " << label << ": " << s.message << ", true error " << s.error.value_or(-1.0) << "\n";
        ASSERT_TRUE(s.error.has_value()) << label;
        if (s.converged()) EXPECT_LE(*s.error, kTolerance) << label << ": " << s.message;
        EXPECT_GT(*s.error, kTolerance) << label << ": ω this small cannot have reached the solution";
        EXPECT_FALSE(s.converged()) << label << ": " << s.message;
      }
  }
}

// The body touching the obstacle at the start (gap 0 at its lowest node) with nothing prescribed to
// move: the solution is zero, every stage returns zero, η = 0.
TEST(FixedPoint, ABodyAtRestOnTheObstacleIsConverged) {
  for (int dimension : {2, 3}) {
    stc::Scene scene = dimension == 3 ? stc::test::hemisphereScene(4, 11) : stc::test::seedScene(21, 11);
    scene.obstacle.point[dimension - 1] = -1.0;  // the pole on the obstacle
    for (auto& d : scene.dirichlet) d.history = {{0.0}, {0.0}};
    const stc::test::StrategyFixture fixture(scene);
    for (const char* strategy : kIterative) {
      const stc::SolveSummary s = fixture.solve(strategy, kTolerance).summary;
      const std::string label = std::to_string(dimension) + "D " + strategy;
      std::cout << "[ measured ] " << label << ": " << s.message << "\n";
      EXPECT_TRUE(s.converged()) << label << ": " << s.message;
      EXPECT_LE(s.indicator, stc::kFixedPointIndicator) << label;
    }
  }
}

// Lifted away from the obstacle and brought back to touch it, rigidly: no strain energy at any
// instant (a rigid motion), contact at the first and last instants.
TEST(FixedPoint, ABodyLiftedAndBroughtBackRigidlyIsConverged) {
  stc::Scene scene = stc::test::seedScene(21, 11);
  scene.obstacle.point[1] = -1.0;
  scene.dirichlet[0].history = {{0.0}, {0.0}};
  scene.dirichlet[1].history = {{0.0, 0.5, 1.0}, {0.0, 0.3, 0.0}};  // up 0.3, then back
  const stc::test::StrategyFixture fixture(scene);
  for (const char* strategy : kIterative) {
    const stc::SolveSummary s = fixture.solve(strategy, kTolerance).summary;
    std::cout << "[ measured ] " << strategy << ": " << s.message << "\n";
    EXPECT_TRUE(s.converged()) << strategy << ": " << s.message;
  }
}

TEST(ControlledStage, AFullGapShareStillMeetsTheTolerance) {
  stc::Scene scene = stc::test::hemisphereScene(4, 21);
  const stc::test::StrategyFixture fixture(scene);
  for (double share : {0.9, 0.99}) {
    stc::SolverSpec spec = scene.solver;
    spec.latin_pgd.stage.gap_share = share;
    spec.setTolerance(kTolerance);
    stc::SolveInputs inputs;
    inputs.reference = &fixture.reference;
    const stc::SolveSummary s = stc::solve(stc::strategyNamed("latin-pgd"), fixture.problem, spec, inputs).summary;
    std::cout << "[ measured ] gap share " << share << ": " << s.message << ", true error " << s.error.value_or(-1.0) << "\n";
    ASSERT_TRUE(s.converged()) << s.message;
    ASSERT_TRUE(s.error.has_value());
    EXPECT_LE(*s.error, kTolerance);
    EXPECT_LE(*s.error, s.error_estimate);  // the estimate bounds it, as at the default share
  }
}

}  // namespace
