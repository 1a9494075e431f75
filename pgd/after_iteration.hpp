#pragma once
// What the separated solvers (`fas-apriori`, `latin-pgd`) do after their last iteration: the spatial
// modes, the separated displacement and the far nodes' lift, whose responses a condensed interface
// or released responses have not solved (pgd/response_basis.hpp). It may be long (at 10⁶ dofs on
// two ranks, before the far nodes' traces were kept, 151 solves and 720 s) and no iteration callback
// sees it: when it may solve, this phase tells SolveInputs::phase_note when it starts and what it
// cost (src/solver/noted_phase.hpp); it counts its solves in the last record
// (SolveSummary::addSolvesAfterIteration).
#include "stcontact/pgd/response_basis.hpp"
#include "stcontact/solver/noted_phase.hpp"
#include "stcontact/solver/solve_inputs.hpp"

namespace stc::pgd {

class AfterIteration {
 public:
  /// Starts the phase; tells phase_note when it may solve: the basis lacks some responses and the
  /// phase needs them, for the spatial modes or the separated displacement that `inputs` asks for,
  /// or for a lift (`lift_solves`: rows whose traces were not kept, ResponseBasis::keepsTracesFor).
  AfterIteration(const ResponseBasis& basis, const SolveInputs& inputs, bool lift_solves = false);
  /// Ends it: counts its solves in `summary`'s last record and tells phase_note how many and how long.
  void finish(SolveSummary& summary) const;

 private:
  const ResponseBasis& basis_;
  NotedPhase phase_;
  long solves_before_;
};

}  // namespace stc::pgd
