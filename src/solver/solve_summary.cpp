#include "stcontact/solver/solve_summary.hpp"

namespace stc {

const char* toString(Termination termination) {
  switch (termination) {
    case Termination::Converged: return "converged";
    case Termination::MaxIterations: return "max_iterations";
    case Termination::Stagnated: return "stagnated";
    case Termination::NumericalIssue: return "numerical_issue";
    case Termination::StoppedByCallback: return "stopped_by_callback";
  }
  return "unknown";
}

}  // namespace stc
