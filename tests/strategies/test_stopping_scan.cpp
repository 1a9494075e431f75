// The stopping rule cannot be fooled (docs/method.md §2, "Stopping"): over the ranges the scene
// reader accepts, "converged" means a true error at most the tolerance. Every iterative strategy, in
// 2D (the seed scene) and 3D (the hemisphere), at small settings, across
//   - the search direction's scale κ R / L over its whole range [0.01, 100], set through κ and
//     through L (k = κ E ℓ_i / L depends on κ / L alone);
//   - the relaxation ω from 0.1 to 1 (latin, latin-pgd; the FAS strategies relax at ω = 1).
// A run that ends otherwise (the iteration limit, stagnation) is an honest answer and passes; a run
// that reports converged must have its true error, measured against the incremental solution, at
// most the tolerance.
#include <gtest/gtest.h>

#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "strategies/strategy_fixture.hpp"

namespace {

constexpr double kTolerance = 1e-6;

struct ScanCase {
  int dimension;
  std::string strategy;
  double search_scale = 4.0;                 ///< κ
  std::optional<double> length_scale;        ///< L (default: the body's size R = 1)
  double relaxation = 1.0;                   ///< ω
};

std::string nameOf(const ScanCase& c) {
  std::string name = std::to_string(c.dimension) + "D_" + c.strategy + "_kappa" + std::to_string(c.search_scale);
  if (c.length_scale) name += "_L" + std::to_string(*c.length_scale);
  if (c.relaxation < 1.0) name += "_omega" + std::to_string(c.relaxation);
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

const stc::test::StrategyFixture& reference(int dimension) { return stc::test::smallFixture(dimension); }

std::vector<ScanCase> scanCases() {
  std::vector<ScanCase> cases;
  for (int dimension : {2, 3}) {
    for (const char* strategy : {"latin", "latin-pgd", "fas-aposteriori", "fas-apriori"}) {
      for (double kappa : {0.01, 0.1, 1.0, 10.0, 100.0}) cases.push_back({dimension, strategy, kappa});
      cases.push_back({dimension, strategy, 4.0, 400.0});  // κ R / L = 0.01
      cases.push_back({dimension, strategy, 4.0, 0.04});   // κ R / L = 100
    }
    for (const char* strategy : {"latin", "latin-pgd"})
      for (double omega : {0.1, 0.3, 0.55, 0.8}) cases.push_back({dimension, strategy, 4.0, std::nullopt, omega});
  }
  return cases;
}

class StoppingScan : public ::testing::TestWithParam<ScanCase> {};

TEST_P(StoppingScan, ConvergedMeansATrueErrorWithinTheTolerance) {
  const ScanCase& c = GetParam();
  const stc::test::StrategyFixture& base = reference(c.dimension);
  stc::Scene scene = base.scene;
  scene.search_direction.scale = c.search_scale;
  scene.contact.length_scale = c.length_scale;
  scene.solver.latin.relaxation = scene.solver.latin_pgd.latin.relaxation = c.relaxation;
  scene.solver.setTolerance(kTolerance);
  // The same mesh, loads and stiffness as the reference's problem: its true-error measure applies.
  const stc::Problem problem = stc::buildProblem(scene);
  const stc::SolveSummary s = base.solveAgainstReference(c.strategy, problem, scene.solver).summary;
  stc::test::printMeasured(nameOf(c), s);
  ASSERT_TRUE(s.error.has_value());
  if (!s.converged()) return;  // an honest answer
  EXPECT_LE(*s.error, kTolerance) << s.message;
  EXPECT_LE(s.error_estimate, kTolerance);
}

// A body that never reaches the obstacle: its solution has no contact force, and no strain energy
// when the prescribed motion is rigid (the relative error is then 0/0). Every iterative strategy
// converges, certified (src/solver/contact_free_certificate.hpp), rather than stagnating on noise;
// with a load that deforms the body, its true error is within the tolerance.
TEST(StoppingWithoutContact, EveryStrategyConvergesCertified) {
  for (int dimension : {2, 3})
    for (bool deformed : {false, true}) {
      stc::Scene scene = dimension == 3 ? stc::test::hemisphereScene(4, 11) : stc::test::seedScene(21, 11);
      scene.obstacle.point[dimension - 1] = -100.0;
      const std::string arc = dimension == 3 ? "contact" : "arc";
      if (deformed) scene.loads.push_back({arc, stc::Component::X, {{0.0, 1.0}, {0.0, 5.0}}});
      const stc::test::StrategyFixture fixture(scene);
      for (const char* strategy : {"latin", "latin-pgd", "fas-aposteriori", "fas-apriori"}) {
        const stc::SolveSummary s = fixture.solve(strategy, kTolerance).summary;
        const std::string label = std::to_string(dimension) + "D " + strategy + (deformed ? " loaded" : " rigid");
        std::cout << "[ measured ] " << label << ": " << s.message << ", true error " << s.error.value_or(-1.0) << "\n";
        EXPECT_TRUE(s.converged()) << label << ": " << s.message;
        EXPECT_EQ(fixture.reference.defined(), deformed) << label;
        if (deformed) {
          ASSERT_TRUE(s.error.has_value()) << label;
          EXPECT_LE(*s.error, kTolerance) << label;
        } else {
          EXPECT_NE(s.message.find("no contact at any instant"), std::string::npos) << label << ": " << s.message;
          EXPECT_NE(s.message.find("no relative error is defined"), std::string::npos) << label;
        }
      }
    }
}

// The coarsest seed mesh (11 arc nodes, a contact zone of 3 nodes) at τ = 1e-4: the FAS strategies'
// first iterate, started from the zone carried rigidly, has an indicator of 0.53 and an error 0.74
// times it, against 2.4 times once the iteration settles. Calibrated on it, the estimate said
// 9.5e-5 at the third iterate while the true error was 1.3e-4; iterates with an indicator of 0.1 or
// more now calibrate nothing (src/solver/calibrated_estimate.hpp).
TEST(StoppingOnACoarseMesh, ThePreAsymptoticFirstIterateCalibratesNothing) {
  for (int steps : {11, 21, 201}) {
    const stc::test::StrategyFixture fixture(stc::test::seedScene(11, steps));
    for (const char* strategy : {"fas-aposteriori", "fas-apriori"}) {
      const stc::SolveSummary s = fixture.solve(strategy, 1e-4).summary;
      const std::string label = std::string(strategy) + ", " + std::to_string(steps) + " instants";
      std::cout << "[ measured ] " << label << ": " << s.message << ", true error " << s.error.value_or(-1.0) << "\n";
      ASSERT_TRUE(s.error.has_value()) << label;
      if (s.converged()) EXPECT_LE(*s.error, 1e-4) << label << ": " << s.message;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AcrossTheRanges, StoppingScan, ::testing::ValuesIn(scanCases()),
                         [](const ::testing::TestParamInfo<ScanCase>& info) { return nameOf(info.param); });

}  // namespace
