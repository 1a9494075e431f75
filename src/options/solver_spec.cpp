#include "stcontact/options/solver_spec.hpp"

namespace stc {

StoppingOptions* SolverSpec::stopping(Strategy s) {
  return const_cast<StoppingOptions*>(static_cast<const SolverSpec&>(*this).stopping(s));
}

const StoppingOptions* SolverSpec::stopping(Strategy s) const {
  switch (s) {
    case Strategy::Latin: return &latin.stop;
    case Strategy::LatinPgd: return &latin_pgd.latin.stop;
    case Strategy::FasAposteriori: return &fas_aposteriori.fas.stop;
    case Strategy::FasApriori: return &fas_apriori.fas.stop;
    case Strategy::Incremental: return nullptr;
  }
  return nullptr;
}

void SolverSpec::setTolerance(double tolerance) {
  for (const auto& [name, s] : kStrategies)
    if (StoppingOptions* stop = stopping(s)) stop->tolerance = tolerance;
}

void SolverSpec::setMaxIterations(int max_iterations) {
  for (const auto& [name, s] : kStrategies)
    if (StoppingOptions* stop = stopping(s)) stop->max_iterations = max_iterations;
}

double SolverSpec::tolerance() const {
  const StoppingOptions* stop = stopping(strategy);
  return stop ? stop->tolerance : latin.stop.tolerance;
}

LinearSolverOptions SolverSpec::linearAtTolerance() const {
  LinearSolverOptions out = linear;
  out.rtol = linear.residualTolerance(tolerance());
  return out;
}

void SolverSpec::validate() const {
  latin.validate();
  latin_pgd.validate();
  fas_aposteriori.validate();
  fas_apriori.validate();
  incremental.validate();
  linear.validate();
}

}  // namespace stc
