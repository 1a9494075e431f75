#pragma once
// What a solve may be given beside its problem and options, the same for every strategy
// (strategies/registry.hpp): a true-error measure, a per-iteration callback, a warm start, and for
// `fas-aposteriori` the converged solution its basis comes from, and the run's prepared operators.
#include <Eigen/Core>

#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/error_measure.hpp"
#include "stcontact/solver/record_origin.hpp"
#include "stcontact/solver/solve_result.hpp"
#include "stcontact/solver/solve_summary.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc {

struct SolveInputs {
  /// Adds the true error to every history record (e.g. an ErrorReference against the incremental
  /// solution, src/incremental/error_reference.hpp).
  const ErrorMeasure* reference = nullptr;
  /// Called after every iteration; returning false stops the solve (Termination::StoppedByCallback).
  IterationCallback callback = {};
  /// Warm start (src/solver/warm_start.hpp): the interface history the iterative strategies start
  /// from instead of s = 0, e.g. a neighbouring problem's SolveResult::interface (d n_C × m).
  /// Ignored by `incremental`, which marches in time from the unloaded state.
  const InterfaceHistory* start = nullptr;
  /// Warm start of a separated global stage: the interface directions `fas-apriori` and `latin-pgd`
  /// begin with (d n_C × p), e.g. a neighbouring problem's SolveResult::interface_directions; they
  /// enrich from there. Ignored by the others.
  const Eigen::MatrixXd* basis_seed = nullptr;
  /// `fas-aposteriori`: a converged solution's contact forces (d n_C × m) whose SVD modes form its
  /// coarse space; computed with the incremental solver when absent. Its cost is not part of the
  /// summary's wall time.
  const Eigen::MatrixXd* converged_lambda = nullptr;
  /// Whether `fas-apriori` and `latin-pgd` return SolveResult::spatial_modes. Rebuilding them is a
  /// product of the n_free × p responses with every mode, after the last iteration (at 1601 contact
  /// nodes, 0.15 s of a 1.07 s solve), and, where the traces came from the factor's trailing block,
  /// the p responses' solves (pgd/response_basis.hpp): programs that do not read them turn this off.
  bool spatial_modes = true;
  /// Whether `fas-apriori` and `latin-pgd` return SolveResult::displacement, their displacement
  /// history in separated form (the run's frames come from it, pgd/separated_history.hpp): after
  /// the last iteration, at most its rank in solves where the factor condensed the interface (the
  /// responses were not solved), none otherwise.
  bool separated_displacement = false;
  /// The run's operators (src/operators/prepared_operators.hpp): a solve takes its factors from
  /// there, preparing each at most once, and leaves them for the run's other users (the reference,
  /// the writer). Null: the solve prepares its own, each once within it.
  PreparedOperators* operators = nullptr;
  /// Where the records count from when this solve is a part of a larger one (record_origin.hpp):
  /// the parts before it and the whole solve's clock. A strategy called on its own starts its clock
  /// on entry (RecordOrigin::clocked), its set-up included.
  RecordOrigin origin = {};
  /// Told, one line each, when the solve enters and leaves a phase outside its iterations that may
  /// take long and that `callback` does not see: `fas-apriori`'s and `latin-pgd`'s displacement
  /// from the converged interface history (the far nodes' lift: at 10⁶ dofs, 151 solves and 720 s
  /// after the last iteration, docs/linear_solvers.md). For a progress display or a log; empty: none.
  PhaseNote phase_note = {};
};

/// Where an iterative solve starts: inputs.start, else s = 0 on `problem`'s interface.
inline InterfaceHistory startingHistory(const Problem& problem, const SolveInputs& inputs) {
  if (inputs.start) return *inputs.start;
  return InterfaceHistory::zeros(problem.contact, problem.numSteps());
}

}  // namespace stc
