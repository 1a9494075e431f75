#include "stcontact/strategies/registry.hpp"

#include <memory>
#include <stdexcept>

#include "stcontact/fas/aposteriori/solve_fas_aposteriori.hpp"
#include "stcontact/fas/apriori/solve_fas_apriori.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/latin/latin_solver.hpp"
#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/pgd/latin_pgd_solver.hpp"

namespace stc {

const std::array<StrategyRegistration, kStrategies.size()>& strategyRegistry() {
  using P = const Problem&;
  using S = const SolverSpec&;
  using I = const SolveInputs&;
  static const std::array<StrategyRegistration, kStrategies.size()> registry = {{
      {Strategy::Latin, [](P p, S s, I in) { return latin::solveLatin(p, s.latin, in); }},
      {Strategy::LatinPgd, [](P p, S s, I in) { return pgd::solveLatinPgd(p, s.latin_pgd, in); }},
      {Strategy::FasAposteriori, [](P p, S s, I in) { return fas::solveFasAposteriori(p, s.fas_aposteriori, in); }},
      {Strategy::FasApriori, [](P p, S s, I in) { return fas::solveFasApriori(p, s.fas_apriori, in); }},
      {Strategy::Incremental, [](P p, S s, I in) { return solveIncremental(p, s.incremental, in); }},
  }};
  return registry;
}

namespace {
// A run whose linear solve failed (an iterative backend that did not reach its tolerance): a
// numerical issue that names the backend and its reason, with zero fields (never a wrong answer).
SolveResult linearSolveFailed(Strategy strategy, const Problem& problem, const LinearSolveFailure& failure) {
  SolveResult out;
  out.interface = InterfaceHistory::zeros(problem.contact, problem.numSteps());
  out.summary.solver = std::string(nameOf(strategy));
  out.summary.termination = Termination::NumericalIssue;
  out.summary.reason = out.summary.message = failure.what();
  return out;
}

SolveResult solveWith(const StrategyRegistration& r, const Problem& problem, const SolverSpec& spec,
                      const SolveInputs& inputs) {
  try {
    return r.solve(problem, spec, inputs);
  } catch (const LinearSolveFailure& failure) {
    return linearSolveFailed(r.strategy, problem, failure);
  }
}
}  // namespace

SolveResult solve(Strategy strategy, const Problem& problem, const SolverSpec& spec, const SolveInputs& inputs) {
  // Without the run's operators, the solve's own, on spec's linear backend.
  SolveInputs with = inputs;
  std::unique_ptr<PreparedOperators> own;
  if (!with.operators) with.operators = (own = std::make_unique<PreparedOperators>(spec.linearAtTolerance())).get();
  const long long before = with.operators->krylovIterations();
  with.origin.krylov = [operators = with.operators, before] { return operators->krylovIterations() - before; };
  for (const StrategyRegistration& r : strategyRegistry())
    if (r.strategy == strategy) {
      SolveResult result = solveWith(r, problem, spec, with);
      result.summary.krylov_iterations = with.origin.krylov();
      result.summary.countKrylovAfterIteration();
      return result;
    }
  throw std::logic_error("strategy without a registration: " + std::string(nameOf(strategy)));
}

}  // namespace stc
