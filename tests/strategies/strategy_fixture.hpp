#pragma once
// A scene solved once by the incremental reference, with the error reference every strategy's true
// error is measured against; `solve` runs a strategy by name at a tolerance.
#include <string>

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

}  // namespace stc::test
