#pragma once
// `fas-apriori`, the default strategy (docs/method.md §5): the two-level FAS on the separated global
// stage (pgd/controlled_global_stage.hpp), its coarse space the leading energy modes of the
// expansion built during the iterations (apriori_basis.hpp), never the SVD of a converged solution;
// solved on the contact nodes that can touch (reduced_interface.hpp) and, on long grids, started
// from a solve on a sub-grid of instants (nested_in_time.hpp).
#include "stcontact/fas/apriori/apriori_basis.hpp"
#include "stcontact/options/fas_apriori_options.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_inputs.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::fas {

/// Solves from inputs.start (s = 0 when none; nested iteration in time only from s = 0), the
/// directions begun from inputs.basis_seed; returns the interface directions, and the spatial modes
/// when inputs.spatial_modes.
SolveResult solveFasApriori(const Problem& problem, const FasAprioriOptions& options, const SolveInputs& inputs = {});

/// The same fine level (separated stage, reduced interface, nested iteration in time, as `options`
/// set them) with the coarse spaces of `coarse_basis`: `fas-aposteriori` on the separated fine level
/// (fas/aposteriori/solve_fas_aposteriori.hpp), so that a comparison of bases changes the basis alone.
SolveResult solveOnSeparatedFineLevel(const Problem& problem, const FasAprioriOptions& options,
                                      const SolveInputs& inputs, const SeparatedCoarseBasis& coarse_basis);

}  // namespace stc::fas
