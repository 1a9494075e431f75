#include "stcontact/solver/solve_summary.hpp"

#include <utility>

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

void SolveSummary::composeMessage() {
  message = reason;
  for (const std::string& remark : remarks) message += "; " + remark;
  for (const SolveStage& stage : stages) message += "; " + stage.description;
}

void SolveSummary::addStage(SolveStage stage) {
  stages.push_back(std::move(stage));
  composeMessage();
}

}  // namespace stc
