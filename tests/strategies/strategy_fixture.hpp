#pragma once
// A scene solved once by the incremental reference, with the error reference every strategy's true
// error is measured against; `solve` runs a strategy by name at a tolerance.
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/incremental/condensed_interface.hpp"
#include "stcontact/incremental/error_reference.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/operators/prepared_operators.hpp"
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

  /// `strategy` on `problem` (this fixture's mesh, loads and stiffness under other settings) with
  /// `spec`, its true error measured against this fixture's reference; `operators` as
  /// SolveInputs::operators.
  SolveResult solveAgainstReference(const std::string& strategy, const Problem& on, const SolverSpec& spec,
                                    PreparedOperators* operators = nullptr) const {
    SolveInputs inputs;
    inputs.reference = &reference;
    inputs.converged_lambda = &incremental.interface.lambda;
    inputs.operators = operators;
    return stc::solve(strategyNamed(strategy), on, spec, inputs);
  }

  SolveResult solve(const std::string& name, double tolerance) const {
    SolverSpec spec = scene.solver;
    spec.setTolerance(tolerance);
    SolveInputs inputs;
    inputs.reference = &reference;
    return stc::solve(strategyNamed(name), problem, spec, inputs);
  }
};

/// "[ measured ] label: converged after n, true error e, estimate x": what a scan prints per case.
inline void printMeasured(const std::string& label, const SolveSummary& s) {
  std::cout << "[ measured ] " << label << ": " << toString(s.termination) << " after " << s.iterations
            << ", true error " << s.error.value_or(-1.0) << ", estimate " << s.error_estimate << "\n";
}

/// The scene of `dimension` at small settings (the seed at 21 arc nodes, the hemisphere at divisions
/// 4; 21 instants), solved once per test program by the incremental reference.
inline const StrategyFixture& smallFixture(int dimension) {
  static std::map<int, std::unique_ptr<StrategyFixture>> fixtures;
  auto& f = fixtures[dimension];
  if (!f) f = std::make_unique<StrategyFixture>(dimension == 3 ? hemisphereScene(4, 21) : seedScene(21, 21));
  return *f;
}

}  // namespace stc::test
