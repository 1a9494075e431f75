#include "stcontact/solver/solve_result.hpp"

namespace stc {

ContactStateTable SolveResult::contactStates(const ContactInterface& contact) const {
  if (!contact_admissible) return {contact, interface};
  if (admissible_nodes.empty()) return {contact, *contact_admissible};
  return {contact, interface, *contact_admissible, admissible_nodes};
}

namespace {

// `all` with the rows of `nodes` (d per node) taken from `part`, in that order.
InterfaceHistory patched(InterfaceHistory all, const InterfaceHistory& part, const std::vector<int>& nodes) {
  const std::vector<int> rows = rowsOfNodes(static_cast<int>(part.v.rows()) / static_cast<int>(nodes.size()), nodes);
  all.v(rows, Eigen::all) = part.v;
  all.lambda(rows, Eigen::all) = part.lambda;
  return all;
}

}  // namespace

InterfaceHistory SolveResult::admissible() const {
  if (!contact_admissible) return interface;
  if (admissible_nodes.empty()) return *contact_admissible;
  return patched(interface, *contact_admissible, admissible_nodes);
}

InterfaceHistory SolveResult::takeAdmissible() && {
  if (!contact_admissible) return std::move(interface);
  if (admissible_nodes.empty()) return std::move(*contact_admissible);
  return patched(std::move(interface), *contact_admissible, admissible_nodes);
}

}  // namespace stc
