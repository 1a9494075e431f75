#include "stcontact/fas/aposteriori/solve_fas_aposteriori.hpp"

#include "stcontact/fas/aposteriori/aposteriori_basis.hpp"
#include "stcontact/fas/aposteriori/fixed_basis_provider.hpp"
#include "stcontact/fas/aposteriori/separated_aposteriori_basis.hpp"
#include "stcontact/fas/apriori/solve_fas_apriori.hpp"
#include "stcontact/fas/fas_solver.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/latin/global_stage.hpp"
#include "stcontact/operators/prepared_operators.hpp"

namespace stc::fas {
namespace {

// The a posteriori basis on `fas-apriori`'s fine level: its pipeline with this provider on each stage.
SolveResult solveOnSeparated(const Problem& problem, const FasAposterioriOptions& options, const SolveInputs& inputs,
                             const Eigen::MatrixXd& modes) {
  FasAprioriOptions fine;
  fine.fas = options.fas;
  static_cast<SeparatedFineLevelOptions&>(fine) = options;
  SeparatedCoarseBasis coarse{"fas-aposteriori", [&](pgd::ControlledGlobalStage& stage, const Problem& on) {
                                return std::make_unique<SeparatedAposterioriProvider>(
                                    modes, options.basis.residual_vectors, stage, on.contact.B);
                              }};
  return solveOnSeparatedFineLevel(problem, fine, inputs, coarse);
}

}  // namespace

SolveResult solveFasAposteriori(const Problem& problem, const FasAposterioriOptions& options,
                                const SolveInputs& inputs) {
  options.validate();
  std::unique_ptr<PreparedOperators> own;
  PreparedOperators& operators = operatorsOr(inputs.operators, own);
  SolveInputs shared = inputs;
  shared.operators = &operators;
  Eigen::MatrixXd lambda;
  if (inputs.converged_lambda) lambda = *inputs.converged_lambda;
  else lambda = solveIncremental(problem, {}, {.operators = &operators}).interface.lambda;
  const Eigen::MatrixXd modes =
      aposterioriModes(problem, *operators.stiffnessFree(problem), lambda, options.basis.svd_modes);
  // The basis is not part of the solve's time: its clock starts now, the stage's set-up included.
  if (options.fine_level == AposterioriFineLevel::Separated) return solveOnSeparated(problem, options, shared, modes);
  shared.origin = inputs.origin.clocked();
  latin::GlobalStage global(problem, operators);
  global.keepDisplacements(true);
  FixedBasisProvider provider(modes, options.basis.residual_vectors, global, problem.contact.B);
  return solveFas(problem, global, provider, options.fas, shared, "fas-aposteriori");
}

}  // namespace stc::fas
