#pragma once
// `fas-apriori` on the contact nodes that can touch (docs/method.md §5, "The reduced interface").
// A potential contact node that stays open at every instant carries no force and imposes nothing:
// the problem without it has the same solution, as long as that solution does not push it into the
// obstacle. Far from the obstacle such nodes are most of a fine interface (on the half-disc with
// 801 arc nodes, about two thirds), and every product of the separated global stage and every local
// stage pays for their rows. So the solve
//   1. finds the zone: when the loading is a prescribed motion alone (no applied force), the nodes
//      within its reach, before any solve (src/problem/prescribed_reach.hpp: gaps that the motion,
//      carried rigidly, closes at some instant), and without a warm start the iteration starts from
//      the interface history of that rigid motion; otherwise, or when that set is empty or above
//      a share of the nodes (ReducedInterfaceOptions::whole_share, three quarters), one relaxation on
//      the whole interface from the start and the nodes of its contact zone (fas/coarse_zone.hpp with
//      a share of its margin, ReducedInterfaceOptions::margin = 1/2: closed at some instant, or
//      nearer the obstacle than δ/2, δ = max |v_n − v̂_n| the largest normal jump of that
//      relaxation; δ when δ/2 leaves no node);
//   2. solves the problem on those nodes alone (restrictToNodes: the same body and loads), its
//      iterates' true error measured with zero forces on the other rows (ErrorOnRows), which is
//      their force in the restricted problem; on a long grid the first round begins on every q-th
//      instant (fas/apriori/nested_in_time.hpp);
//   3. checks the nodes left out: their normal displacement B_F u, one product with the separated
//      displacement history u = U_F G + X c, must keep g0 + v_n ≥ 0 at every instant. The solution
//      then satisfies every condition of the whole problem (equilibrium with λ_F = 0, the contact
//      law on the zone, open far nodes). Nodes that penetrate join the zone and the solve goes on from
//      where it stopped; after ReducedInterfaceOptions::rounds such rounds the whole interface is solved. A restricted
//      round gets half of the iterations left; one that does not converge within them gives way to
//      the whole interface, from where it stopped (from the first start after a numerical issue).
// The result is lifted to the whole interface: λ = 0 and v = B_F u on the nodes left out. Counts and
// times include the first relaxation, when there is one, and everything before the restricted solve's
// first iteration; the summary records the rounds as a stage (SolveStage::ContactZone).
// One file per level: step 1 here, the rounds of steps 2–3 in zone_rounds.hpp, each round's solve in
// single_solve.hpp.
#include "stcontact/fas/apriori/apriori_basis.hpp"
#include "stcontact/options/fas_apriori_options.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_inputs.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::fas {

/// `fas-apriori` with the interface reduced to its contact zone (the header's steps 1–3). Falls back
/// to the whole interface when the first relaxation's zone holds more than options.zone.whole_share
/// of the nodes.
SolveResult solveAprioriOnContactZone(const Problem& problem, const FasAprioriOptions& options,
                                      const SolveInputs& inputs, const SeparatedCoarseBasis& coarse_basis = {});

}  // namespace stc::fas
