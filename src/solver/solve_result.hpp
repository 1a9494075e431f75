#pragma once
// A solver's output: the interface histories (full fields are rebuilt from them on demand,
// see condensed_interface.hpp) and the summary.
#include "src/solver/solve_summary.hpp"
#include "src/spacetime/interface_history.hpp"

namespace stc {

struct SolveResult {
  InterfaceHistory interface;
  SolveSummary summary;
};

}  // namespace stc
