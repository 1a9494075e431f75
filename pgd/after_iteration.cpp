#include "stcontact/pgd/after_iteration.hpp"

#include <string>

namespace stc::pgd {

AfterIteration::AfterIteration(const ResponseBasis& basis, const SolveInputs& inputs, bool lift_solves)
    : basis_(basis), phase_(inputs.phase_note, "after the last iteration: "), solves_before_(basis.sparseSolves()) {
  const bool lacks_responses = basis.condensesInterface() || !basis.holdsResponses();
  const bool needs_responses = inputs.spatial_modes || inputs.separated_displacement || lift_solves;
  if (lacks_responses && needs_responses && basis.size() > 0)
    phase_.begin("the displacement from the converged history, at most " + std::to_string(basis.size()) +
                 " sparse solves");
}

void AfterIteration::finish(SolveSummary& summary) const {
  const long solves = basis_.sparseSolves() - solves_before_;
  summary.addSolvesAfterIteration(solves);
  phase_.end(solves);
}

}  // namespace stc::pgd
