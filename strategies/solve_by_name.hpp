#pragma once
// Every strategy behind one call, chosen by its docs/interface.md name: `incremental`, `latin`,
// `latin-pgd`, `fas-aposteriori`, `fas-apriori`. What the command line and the comparison and sweep
// programs use.
#include <string>
#include <vector>

#include "stcontact/fas/apriori/apriori_basis.hpp"
#include "stcontact/fas/fas_options.hpp"
#include "stcontact/incremental/error_reference.hpp"
#include "stcontact/pgd/controlled_global_stage.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc {

/// The strategies' names (kSolverNames of src/core/solver_settings.hpp).
const std::vector<std::string>& availableSolvers();
/// Throws InputError for an unknown name.
void requireAvailable(const std::string& name);

struct StrategyInputs {
  const ErrorReference* reference = nullptr;  ///< adds the true error to the history
  /// A converged solution's contact forces (2n_C × m) for `fas-aposteriori`; computed with the
  /// incremental solver when absent. Its cost is not part of the FAS summary's wall time.
  const Eigen::MatrixXd* converged_lambda = nullptr;
  IterationCallback callback;
  /// Warm start (src/solver/warm_start.hpp): the interface history the iterative strategies start
  /// from instead of s = 0, e.g. a neighbouring problem's SolveResult::interface (2n_C × m).
  /// Ignored by `incremental`, which marches in time from the unloaded state.
  const InterfaceHistory* start = nullptr;
  /// Warm start of an a priori basis: the interface directions `fas-apriori` and `latin-pgd` begin
  /// with (2n_C × p), e.g. a neighbouring problem's SolveResult::interface_directions; they enrich
  /// from there. Ignored by the others (`fas-aposteriori` takes its modes from `converged_lambda`).
  const Eigen::MatrixXd* basis_seed = nullptr;
  /// Whether `fas-apriori` and `latin-pgd` return SolveResult::spatial_modes. Rebuilding them is a
  /// product of the n_free × p responses with every mode, after the last iteration (at 1601 contact
  /// nodes, 0.15 s of a 1.07 s solve): programs that do not read them turn this off.
  bool spatial_modes = true;
};

/// The FAS options, the a priori basis options and the separated stage's options a SolverSpec sets
/// (for programs that build the solvers themselves, e.g. to inspect the basis).
fas::FasOptions fasOptions(const SolverSpec& spec);
fas::AprioriBasisOptions aprioriOptions(const SolverSpec& spec);
pgd::ControlledStageOptions stageOptions(const SolverSpec& spec);

SolveResult solveByName(const std::string& name, const Problem& problem, const SolverSpec& spec,
                        const StrategyInputs& inputs = {});

}  // namespace stc
