#include "stcontact/strategies/solve_by_name.hpp"

#include <algorithm>

#include "stcontact/core/input_error.hpp"
#include "stcontact/fas/aposteriori/aposteriori_basis.hpp"
#include "stcontact/fas/apriori/apriori_basis.hpp"
#include "stcontact/fas/apriori/reduced_interface.hpp"
#include "stcontact/fas/fas_solver.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/latin/latin_solver.hpp"
#include "stcontact/pgd/latin_pgd_solver.hpp"
#include "stcontact/pgd/separated_history.hpp"

namespace stc {

fas::FasOptions fasOptions(const SolverSpec& spec) {
  fas::FasOptions o;
  o.tolerance = spec.tolerance;
  o.max_relaxations = spec.max_iterations;
  o.pre_relaxations = spec.fas.pre_relaxations;
  o.post_relaxations = spec.fas.post_relaxations;
  o.coarse_iterations = spec.fas.coarse_iterations;
  o.coarse_anderson = spec.fas.coarse_anderson;
  o.coarse_zone = spec.fas.coarse_zone;
  o.start = spec.fas.coarse_start;
  o.adapt_coarse_iterations = spec.fas.adapt_coarse_iterations;
  o.safeguard_growth = spec.fas.safeguard_growth;
  return o;
}

fas::AprioriBasisOptions aprioriOptions(const SolverSpec& spec) {
  fas::AprioriBasisOptions basis;
  basis.modes = spec.fas.pgd_max_modes;
  basis.increment_modes = spec.fas.pgd_increment_modes;
  basis.anticipate = spec.fas.pgd_anticipate;
  return basis;
}

pgd::ControlledStageOptions stageOptions(const SolverSpec& spec) {
  pgd::ControlledStageOptions stage;
  stage.gap_share = spec.fas.pgd_gap_share;
  stage.tolerance = spec.tolerance;
  return stage;
}

namespace {

InterfaceHistory startOf(const Problem& problem, const StrategyInputs& inputs) {
  if (inputs.start) return *inputs.start;
  return InterfaceHistory::zeros(problem.contact, problem.numSteps());
}

SolveResult solveAposteriori(const Problem& problem, const SolverSpec& spec, const StrategyInputs& inputs) {
  const SpdFactor K(problem.stiffness_free, "K_ff");
  Eigen::MatrixXd lambda;
  if (inputs.converged_lambda) lambda = *inputs.converged_lambda;
  else lambda = solveIncremental(problem).interface.lambda;
  const Eigen::MatrixXd modes = fas::aposterioriModes(problem, K, lambda, spec.fas.svd_modes);
  latin::GlobalStage global(problem);
  global.keepDisplacements(true);
  fas::FixedBasisProvider provider(modes, spec.fas.residual_vectors, global, problem.contact.B);
  return fas::solveFas(problem, global, provider, startOf(problem, inputs), fasOptions(spec), "fas-aposteriori",
                       inputs.reference, inputs.callback);
}

SolveResult solveApriori(const Problem& problem, const SolverSpec& spec, const StrategyInputs& inputs) {
  if (spec.fas.reduce_interface && problem.contact.size() > 0) return solveAprioriOnContactZone(problem, spec, inputs);
  Eigen::MatrixXd none;
  SolverSpec own = spec;
  if (inputs.start) own.fas.nested_instants = 0;  // nested iteration in time begins from scratch
  return solveAprioriOn(problem, own, startOf(problem, inputs), inputs.basis_seed, inputs.reference, inputs.callback,
                        Eigen::SparseMatrix<double>(0, problem.numFreeDofs()), none, inputs.spatial_modes);
}

SolveResult solveLatinPgd(const Problem& problem, const SolverSpec& spec, const StrategyInputs& inputs) {
  pgd::LatinPgdOptions options;
  options.stage = stageOptions(spec);
  options.latin.tolerance = spec.tolerance;
  options.latin.max_iterations = spec.max_iterations;
  options.latin.relaxation = spec.relaxation;
  options.spatial_modes = inputs.spatial_modes;
  const InterfaceHistory start = startOf(problem, inputs);
  return pgd::solveLatinPgd(problem, options, &start, inputs.basis_seed, inputs.reference, inputs.callback);
}

SolveResult solveLatinFrom(const Problem& problem, const SolverSpec& spec, const StrategyInputs& inputs) {
  latin::LatinOptions options;
  options.tolerance = spec.tolerance;
  options.max_iterations = spec.max_iterations;
  options.relaxation = spec.relaxation;
  latin::GlobalStage global(problem, options.block_size);
  return latin::solveLatin(problem, global, startOf(problem, inputs), options, inputs.reference, inputs.callback);
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

const std::vector<std::string>& availableSolvers() {
  static const std::vector<std::string> names(kSolverNames.begin(), kSolverNames.end());
  return names;
}

void requireAvailable(const std::string& name) {
  const auto& names = availableSolvers();
  if (std::find(names.begin(), names.end(), name) == names.end())
    throw InputError("unknown solver '" + name + "' (known: " + joined(names) + ")");
}

SolveResult solveByName(const std::string& name, const Problem& problem, const SolverSpec& spec,
                        const StrategyInputs& inputs) {
  requireAvailable(name);
  if (name == "incremental") return solveIncremental(problem, {}, inputs.callback);
  if (name == "fas-aposteriori") return solveAposteriori(problem, spec, inputs);
  if (name == "fas-apriori") return solveApriori(problem, spec, inputs);
  if (name == "latin-pgd") return solveLatinPgd(problem, spec, inputs);
  return solveLatinFrom(problem, spec, inputs);
}

}  // namespace stc
