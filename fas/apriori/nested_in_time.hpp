#pragma once
// Nested iteration in time for `fas-apriori` (docs/method.md §5, "Nested iteration in time"). On a
// long grid the first relaxations of a space-time solve only find the shape of the solution, at the
// price of full passes over every instant. The same problem on every q-th instant
// (src/problem/time_subgrid.hpp) has that shape at about 1/q of the cost per pass; so, with one
// separated stage (its factorisation and directions belong to the space, not to the grid):
//   1. solve the problem on the sub-grid, from the start taken at its instants, to the tolerance
//      max(τ, NestedInTimeOptions::tolerance), the stage retimed to it (pgd::ControlledGlobalStage::retime);
//   2. interpolate its interface history linearly in time onto the whole grid
//      (src/spacetime/time_interpolation.hpp): the start of the solve on the whole grid, with the
//      directions the sub-grid solve built;
//   3. solve on the whole grid from there, to the tolerance τ.
// The start changes where the iteration begins, not its fixed point (src/solver/warm_start.hpp): the
// solution is that of the whole grid. This is the start of full multigrid (Briggs, Henson, McCormick,
// "A Multigrid Tutorial", 2000, ch. 3: the coarse solution interpolated is the fine level's first
// guess), with a coarse level in time.
// Counts and times: the result's history holds the relaxations on the whole grid; its times and
// sparse solves include the sub-grid solve, and the summary records it as a stage (SolveStage::SubGrid).
#include "stcontact/fas/apriori/apriori_basis.hpp"
#include "stcontact/options/fas_apriori_options.hpp"
#include "stcontact/pgd/controlled_global_stage.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/noted_phase.hpp"
#include "stcontact/solver/solve_inputs.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::fas {

/// The stride q of the sub-grid for m instants and a sub-grid of about `coarse_instants` instants:
/// q = ⌊(m − 1) / (coarse_instants − 1)⌋, at most `max_stride` (0: no bound); the sub-grid then has
/// at least `coarse_instants` instants. 0 (no nesting) when coarse_instants < 2 or q < 2.
int nestedStride(int m, int coarse_instants, int max_stride = 0);

/// The sub-grid solve's progress, which no iteration line covers (its records are its own), told
/// through `phase` (at most a line per its interval, NotedPhase::during): "on every 10th instant (201
/// instants): relaxation 12, estimate 3.10e-03, 412 sparse solves, 184.0 s" (at 10⁶ dofs the sub-grid
/// solve of the fretting history took more than 40 minutes on two ranks). It never stops the solve.
IterationCallback subgridProgress(NotedPhase& phase);

/// `fas-apriori`'s FAS cycle on `problem` with `stage` (built for it) from inputs.start: when
/// q = nestedStride(m, options.nested.instants, options.nested.max_stride) ≥ 2 and the stage's backend
/// is direct (or options.nested.on_iterative: NestedInTimeOptions::nestsOn), first on every q-th
/// instant (and the last) from the start at those instants, to the tolerance
/// max(τ, options.nested.tolerance), then on the whole grid from that solution interpolated in time
/// (the header's steps); when the sub-grid solve does not converge, the whole grid from the start,
/// and the stage recorded in the summary says so (its time and solves still count). Callers turn nesting off (options.nested.instants = 0) for a warm
/// start or a later round of the reduced interface. The coarse spaces come from `coarse_basis`.
SolveResult solveFasNestedInTime(const Problem& problem, pgd::ControlledGlobalStage& stage,
                                 const FasAprioriOptions& options, const SolveInputs& inputs,
                                 const SeparatedCoarseBasis& coarse_basis = {});

}  // namespace stc::fas
