#pragma once
// What the separated solvers (`fas-apriori`, `latin-pgd`) do after their last iteration: the spatial
// modes, the separated displacement and the far nodes' lift, whose responses a condensed interface
// or released responses have not solved (pgd/response_basis.hpp). It may be long (at 10⁶ dofs on
// two ranks, 151 solves and 720 s, docs/linear_solvers.md) and no iteration callback sees it: this
// phase tells SolveInputs::phase_note when it starts and what it cost (src/solver/noted_phase.hpp),
// and counts its solves in the last record (SolveSummary::addSolvesAfterIteration).
#include "stcontact/pgd/response_basis.hpp"
#include "stcontact/solver/noted_phase.hpp"
#include "stcontact/solver/solve_inputs.hpp"

namespace stc::pgd {

class AfterIteration {
 public:
  /// Starts the phase; tells phase_note when it may solve (the basis lacks some responses).
  AfterIteration(const ResponseBasis& basis, const SolveInputs& inputs);
  /// Ends it: counts its solves in `summary`'s last record and tells phase_note how many and how long.
  void finish(SolveSummary& summary) const;

 private:
  const ResponseBasis& basis_;
  NotedPhase phase_;
  long solves_before_;
};

}  // namespace stc::pgd
