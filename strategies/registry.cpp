#include "stcontact/strategies/registry.hpp"

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
}  // namespace

SolveResult solve(Strategy strategy, const Problem& problem, const SolverSpec& spec, const SolveInputs& inputs) {
  for (const StrategyRegistration& r : strategyRegistry())
    if (r.strategy == strategy) try {
        return r.solve(problem, spec, inputs);
      } catch (const LinearSolveFailure& failure) {
        return linearSolveFailed(strategy, problem, failure);
      }
  throw std::logic_error("strategy without a registration: " + std::string(nameOf(strategy)));
}

}  // namespace stc
