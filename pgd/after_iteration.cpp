#include "stcontact/pgd/after_iteration.hpp"

#include <cstdio>
#include <string>

namespace stc::pgd {

AfterIteration::AfterIteration(const ResponseBasis& basis, const SolveInputs& inputs)
    : basis_(basis),
      note_(inputs.phase_note),
      solves_before_(basis.sparseSolves()),
      started_(std::chrono::steady_clock::now()) {
  const bool lacks_responses = basis.condensesInterface() || !basis.holdsResponses();
  if (note_ && lacks_responses && basis.size() > 0)
    note_("after the last iteration: the displacement from the converged history, at most " +
          std::to_string(basis.size()) + " sparse solves");
}

void AfterIteration::finish(SolveSummary& summary) const {
  const long solves = basis_.sparseSolves() - solves_before_;
  summary.addSolvesAfterIteration(solves);
  if (!note_ || solves == 0) return;
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - started_;
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.1f s", took.count());
  note_("after the last iteration: " + std::to_string(solves) + " sparse solves, " + seconds);
}

}  // namespace stc::pgd
