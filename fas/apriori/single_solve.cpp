#include "stcontact/fas/apriori/single_solve.hpp"

#include <memory>

#include "stcontact/fas/apriori/nested_in_time.hpp"
#include "stcontact/linalg/dense_product.hpp"
#include "stcontact/pgd/after_iteration.hpp"
#include "stcontact/pgd/controlled_global_stage.hpp"
#include "stcontact/pgd/separated_history.hpp"

namespace stc::fas {
SolveResult solveAprioriOn(const Problem& problem, const FasAprioriOptions& options, const SolveInputs& inputs,
                           const Eigen::SparseMatrix<double>& B_far, Eigen::MatrixXd& far_v,
                           const SeparatedCoarseBasis& coarse_basis) {
  SolveInputs counted = inputs;
  counted.origin = inputs.origin.clocked();  // the stage's set-up on the solve's clock
  std::unique_ptr<PreparedOperators> own;
  pgd::ControlledGlobalStage stage(problem, options.stage, operatorsOr(inputs.operators, own));
  if (B_far.rows() > 0) stage.keepTracesOn(B_far);  // the far nodes' lift with no solve (below)
  stage.notePhases(inputs.phase_note);  // where a long enrichment is
  if (inputs.basis_seed) stage.seed(*inputs.basis_seed);
  // The loads' responses and a warm start's directions, solved before the iteration.
  counted.origin.sparse_solves += stage.sparseSolves();
  SolveResult result = solveFasNestedInTime(problem, stage, options, counted, coarse_basis);
  result.interface_directions = stage.basis().directions();
  // What follows the iteration may solve: the responses of the spatial modes and of the separated
  // displacement, the far nodes' lift (response_basis.hpp); the last record counts those solves.
  // The lift and the separated displacement may each drop what the converged estimate leaves of the
  // tolerance (pgd::truncationBudget): with ε_est bounding the true error e, each is within
  // e + (τ − ε_est) ≤ τ of the reference in the true error's measure (triangle inequality). When the
  // separated displacement is asked for, the far nodes' displacement is its trace, B_F Y_ρ (Σ_ρ W_ρᵀ):
  // the same truncation, no solve of its own, and the written fields and interface agree there.
  // Else, where each direction's response was solved, their traces on the far rows were kept as
  // they came (ResponseBasis::keepTracesOn): B_F (U_F G + X c) exactly, with no solve, even once X
  // was released; where the factor condensed the interface, the lift solves through the rank.
  const bool far_traces_kept = stage.basis().keepsTracesFor(stage.coordinates().rows());
  const pgd::AfterIteration after(stage.basis(), inputs, /*lift_solves=*/B_far.rows() > 0 && !far_traces_kept);
  const double budget = pgd::truncationBudget(result.summary, options.fas.stop.tolerance);
  if (inputs.spatial_modes) result.spatial_modes = pgd::energyModes(stage.basis(), stage.coordinates());
  if (inputs.separated_displacement)
    result.displacement = pgd::separatedDisplacement(stage.basis(), stage.coordinates(), budget);
  if (result.displacement.held)
    far_v = linalg::freshProduct(B_far * result.displacement.modes, result.displacement.time);
  else if (far_traces_kept)
    far_v = stage.basis().displacementOnKeptRows(stage.coordinates());
  else
    far_v = stage.basis().displacementOn(B_far, stage.coordinates(), budget);
  after.finish(result.summary);
  return result;
}

}  // namespace stc::fas
