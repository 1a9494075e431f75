#pragma once
// Nested iteration in time for `fas-apriori` (docs/method.md §5, "Nested iteration in time"). On a
// long grid the first relaxations of a space-time solve only find the shape of the solution, at the
// price of full passes over every instant. The same problem on every q-th instant
// (src/problem/time_subgrid.hpp) has that shape at about 1/q of the cost per pass; so, with one
// separated stage (its factorisation and directions belong to the space, not to the grid):
//   1. solve the problem on the sub-grid, from the start taken at its instants, to the tolerance
//      max(τ, kNestedTolerance), the stage retimed to it (pgd::ControlledGlobalStage::retime);
//   2. interpolate its interface history linearly in time onto the whole grid
//      (src/spacetime/time_interpolation.hpp): the start of the solve on the whole grid, with the
//      directions the sub-grid solve built;
//   3. solve on the whole grid from there, to the tolerance τ.
// The start changes where the iteration begins, not its fixed point (src/solver/warm_start.hpp): the
// solution is that of the whole grid. This is the start of full multigrid (Briggs, Henson, McCormick,
// "A Multigrid Tutorial", 2000, ch. 3: the coarse solution interpolated is the fine level's first
// guess), with a coarse level in time.
// Counts and times: the result's history holds the relaxations on the whole grid; its times and
// sparse solves include the sub-grid solve, and the summary's message says what that cost.
#include "stcontact/pgd/controlled_global_stage.hpp"
#include "stcontact/strategies/solve_by_name.hpp"

namespace stc {

/// The stride q of the sub-grid for m instants and a sub-grid of about `coarse_instants` instants:
/// q = ⌊(m − 1) / (coarse_instants − 1)⌋, the sub-grid then has at least `coarse_instants`
/// instants. 0 (no nesting) when coarse_instants < 2 or q < 2.
int nestedStride(int m, int coarse_instants);

/// `fas-apriori`'s FAS cycle on `problem` with `stage` (built for it) from `start`: when
/// q = nestedStride(m, spec.fas.nested_instants) ≥ 2, first on every q-th instant (and the last) from
/// `start` at those instants, then on the whole grid from that solution interpolated in time (the
/// header's steps); when the sub-grid solve does not converge, the whole grid from `start`, and the
/// message says so (its time and solves still count). Callers turn nesting off with
/// spec.fas.nested_instants = 0 for a warm start or a later round of the reduced interface.
SolveResult solveFasNestedInTime(const Problem& problem, pgd::ControlledGlobalStage& stage, const SolverSpec& spec,
                                 const InterfaceHistory& start, const ErrorMeasure* reference,
                                 const IterationCallback& callback);

}  // namespace stc
