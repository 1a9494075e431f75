#include "stcontact/studies/solve_on_ranks.hpp"

#include "stcontact/core/input_error.hpp"

namespace stc {

void requireBackendForRanks(const Scene& scene, const Ranks& ranks) {
  if (ranks.size > 1 && scene.solver.linear.backend == LinearBackend::Cholmod)
    throw InputError("solver.linear = \"cholmod\" runs in one process; on " + std::to_string(ranks.size) +
                     " ranks choose \"mumps\" or \"cg-gamg\" (--set solver.linear='\"mumps\"')");
  scene.solver.linear.requireGroupsDivide(ranks.size);
}

OutputSpec outputsOnRanks(const Scene& scene, const Ranks& ranks, const SolveResult& result, std::string& note) {
  OutputSpec output = scene.output;
  note.clear();
  if (ranks.size > 1 && output.frames && !result.displacement.held) {
    note = "no frames on " + std::to_string(ranks.size) + " ranks from " + std::string(scene.solver.name()) +
           ", which holds no displacement (fas-apriori and latin-pgd do); solution.h5 holds the rest";
    output.frames = false;
  }
  return output;
}

}  // namespace stc
