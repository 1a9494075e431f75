#pragma once
// A solver's output: the interface histories (full fields are rebuilt from them on demand,
// see condensed_interface.hpp) and the summary.
#include <optional>

#include "src/solver/solve_summary.hpp"
#include "src/spacetime/interface_history.hpp"

namespace stc {

struct SolveResult {
  InterfaceHistory interface;  ///< the solution: for LATIN the last global-stage (equilibrated) iterate
  SolveSummary summary;
  /// The last iterate that satisfies the contact law exactly (LATIN's last local stage ŝ), when it
  /// differs from `interface`; the writers classify open/stick/slip from it.
  std::optional<InterfaceHistory> contact_admissible;

  const InterfaceHistory& admissible() const { return contact_admissible ? *contact_admissible : interface; }
};

}  // namespace stc
