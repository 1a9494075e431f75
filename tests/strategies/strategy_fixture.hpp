#pragma once
// A scene solved once by the incremental reference, with the error reference every strategy's true
// error is measured against; `solve` runs a strategy by name at a tolerance.
#include <map>
#include <memory>
#include <string>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/incremental/condensed_interface.hpp"
#include "stcontact/incremental/error_reference.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/scene/scene.hpp"
#include "stcontact/strategies/registry.hpp"

namespace stc::test {

struct StrategyFixture {
  explicit StrategyFixture(Scene s) : scene(std::move(s)) {}
  Scene scene;
  Problem problem = buildProblem(scene);
  SolveResult incremental = solveIncremental(problem);
  CholmodFactor K{problem.stiffness_free, "K"};
  ErrorReference reference{problem, K, CondensedInterface::build(problem, K).delassus, incremental.interface.lambda};

  SolveResult solve(const std::string& name, double tolerance) const {
    SolverSpec spec = scene.solver;
    spec.setTolerance(tolerance);
    SolveInputs inputs;
    inputs.reference = &reference;
    return stc::solve(strategyNamed(name), problem, spec, inputs);
  }
};

/// The scene of `dimension` at small settings (the seed at 21 arc nodes, the hemisphere at divisions
/// 4; 21 instants), solved once per test program by the incremental reference.
inline const StrategyFixture& smallFixture(int dimension) {
  static std::map<int, std::unique_ptr<StrategyFixture>> fixtures;
  auto& f = fixtures[dimension];
  if (!f) f = std::make_unique<StrategyFixture>(dimension == 3 ? hemisphereScene(4, 21) : seedScene(21, 21));
  return *f;
}

}  // namespace stc::test
