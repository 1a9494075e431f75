#pragma once
// Every strategy behind one call: the registry of (strategy, solve), like PETSc's SNESRegisterAll
// (src/snes/interface/snesregi.c). Each entry calls its strategy's solve with its options from the
// scene's [solver] table (src/options/solver_spec.hpp):
//   solveX(const Problem&, const XOptions&, const SolveInputs&)
// Adding a strategy: its folder with solveX, its options struct in src/options/ (a member of
// SolverSpec), its name in src/options/strategy.hpp, and one line here.
#include <array>

#include "stcontact/options/solver_spec.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_inputs.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc {

using StrategySolve = SolveResult (*)(const Problem&, const SolverSpec&, const SolveInputs&);

struct StrategyRegistration {
  Strategy strategy;
  StrategySolve solve;
};

/// The registered strategies, in the order of kStrategies.
const std::array<StrategyRegistration, kStrategies.size()>& strategyRegistry();

/// Solves `problem` with `strategy`, its options taken from `spec`, its operators from
/// inputs.operators (without them, its own on spec.linearAtTolerance(): InputError for a linear
/// tolerance looser than it allows); summary.krylov_iterations counts what its linear solves took.
SolveResult solve(Strategy strategy, const Problem& problem, const SolverSpec& spec, const SolveInputs& inputs = {});

/// Solves `problem` with the strategy `spec` names (solver.name).
inline SolveResult solve(const Problem& problem, const SolverSpec& spec, const SolveInputs& inputs = {}) {
  return solve(spec.strategy, problem, spec, inputs);
}

}  // namespace stc
