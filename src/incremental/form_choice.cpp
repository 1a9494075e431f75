#include "stcontact/incremental/form_choice.hpp"

#include "stcontact/incremental/whole_body_newton.hpp"

namespace stc {

FormChoice chooseIncrementalForm(IncrementalForm requested, const Problem& problem, const SpdSolver& stiffness,
                                 const std::optional<std::vector<int>>& zone) {
  if (requested != IncrementalForm::Auto) return {requested, {}};
  if (!stiffness.holdsDofs()) return {IncrementalForm::Interface, {}};  // the one form there: nothing weighed
  const std::string head = "incremental form (auto): ";
  if (const std::string why = wholeBodyRefusal(problem, stiffness); !why.empty())
    return {IncrementalForm::Interface, head + "interface; the whole-body form cannot run: " + why};
  if (!zone)
    return {IncrementalForm::Interface,
            head + "interface; no zone within reach says how many column solves it would make"};
  const long columns = columnSolves(problem, zone->size());
  const int m = problem.numSteps();
  const std::string weighed = std::to_string(m) + " instants (the whole-body form: at least a solve each) against " +
                              std::to_string(columns) + " column solves for the " + std::to_string(zone->size()) +
                              " nodes within reach (the interface form)";
  if (m < columns) return {IncrementalForm::WholeBody, head + "whole-body; " + weighed};
  return {IncrementalForm::Interface, head + "interface; " + weighed};
}

long columnSolves(const Problem& problem, std::size_t zone_nodes) {
  return static_cast<long>(problem.contact.dimension) * static_cast<long>(zone_nodes);
}

bool interfaceIsCheaper(int k, int m, long columns, const MarchCost& so_far, std::optional<double> krylov_per_column) {
  if (so_far.instants < kInstantsBeforeWeighing || so_far.solves <= 0) return false;
  const double solves_left = static_cast<double>(m - k) * static_cast<double>(so_far.solves) / so_far.instants;
  const double per_solve = static_cast<double>(so_far.krylov) / static_cast<double>(so_far.solves);
  const double per_column = krylov_per_column.value_or(per_solve);
  return solves_left * per_solve > static_cast<double>(columns) * per_column;
}

}  // namespace stc
