#pragma once
// Nested iteration in time for `fas-apriori` (docs/method.md §5, "Nested iteration in time"). On a
// long grid the first relaxations of a space-time solve only find the shape of the solution, at the
// price of full passes over every instant. The same problem on every q-th instant
// (src/problem/time_subgrid.hpp) has that shape at a tenth of the cost per pass when q = 10; so
//   1. solve the problem on the sub-grid, to the tolerance max(τ, kNestedTolerance);
//   2. interpolate its interface history linearly in time onto the whole grid
//      (src/spacetime/time_interpolation.hpp): the start of the solve on the whole grid; its
//      interface directions, which do not depend on the grid, seed that solve's separated stage;
//   3. solve on the whole grid from there, to the tolerance τ.
// The start changes where the iteration begins, not its fixed point (src/solver/warm_start.hpp): the
// solution is that of the whole grid. This is the start of full multigrid (Briggs, Henson, McCormick,
// "A Multigrid Tutorial", 2000, ch. 3: the coarse solution interpolated is the fine level's first
// guess), with a coarse level in time.
// Counts and times: the result's history holds the relaxations on the whole grid; its times and
// sparse solves include the sub-grid solve, and the summary's message says what that cost.
#include <functional>

#include "src/strategies/solve_by_name.hpp"

namespace stc {

/// The stride q of the sub-grid for m instants and a sub-grid of about `coarse_instants` instants:
/// q = ⌊(m − 1) / (coarse_instants − 1)⌋, the sub-grid then has at least `coarse_instants`
/// instants. 0 (no nesting) when coarse_instants = 0 or q < 2.
int nestedStride(int m, int coarse_instants);

using StrategySolve = std::function<SolveResult(const Problem&, const SolverSpec&, const StrategyInputs&)>;

/// `solve` on the whole grid started from its own solution on every q-th instant
/// (q = nestedStride(m, spec.fas.nested_instants)); `solve` alone when q = 0 or with a warm start
/// (inputs.start). When the sub-grid solve does not converge, the whole grid is solved as if it had
/// not been tried, and the message says so (its time still counts).
SolveResult solveNestedInTime(const Problem& problem, const SolverSpec& spec, const StrategyInputs& inputs,
                              const StrategySolve& solve);

}  // namespace stc
