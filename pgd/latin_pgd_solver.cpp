#include "stcontact/pgd/latin_pgd_solver.hpp"

#include "stcontact/latin/latin_solver.hpp"
#include "stcontact/pgd/after_iteration.hpp"
#include "stcontact/pgd/controlled_global_stage.hpp"
#include "stcontact/pgd/separated_history.hpp"

namespace stc::pgd {

SolveResult solveLatinPgd(const Problem& problem, const LatinPgdOptions& options, const SolveInputs& inputs) {
  options.validate();
  SolveInputs counted = inputs;
  counted.origin = inputs.origin.clocked();  // the stage's set-up on the solve's clock
  std::unique_ptr<PreparedOperators> own;
  ControlledGlobalStage stage(problem, options.stage, operatorsOr(inputs.operators, own));
  stage.notePhases(inputs.phase_note);  // where a long enrichment is
  if (inputs.basis_seed) stage.seed(*inputs.basis_seed);
  // The loads' responses and a warm start's directions, solved before the iteration.
  counted.origin.sparse_solves += stage.sparseSolves();
  SolveResult result = latin::solveLatinWith(problem, stage, options.latin, counted, "latin-pgd");
  result.interface_directions = stage.basis().directions();
  // The spatial modes and the separated displacement need responses, which a condensed interface
  // has not solved yet (response_basis.hpp): the last record counts those solves.
  const AfterIteration after(stage.basis(), inputs);
  if (inputs.spatial_modes) result.spatial_modes = energyModes(stage.basis(), stage.coordinates());
  if (inputs.separated_displacement)
    result.displacement = separatedDisplacement(stage.basis(), stage.coordinates(),
                                                truncationBudget(result.summary, options.latin.stop.tolerance));
  after.finish(result.summary);
  return result;
}

}  // namespace stc::pgd
