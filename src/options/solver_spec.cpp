#include "stcontact/options/solver_spec.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "stcontact/core/input_error.hpp"

namespace stc {
namespace {
std::string formatOption(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}
}  // namespace

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

// A looser linear solve than 1e-4 τ moves the iteration's fixed point by more than the tolerance it
// is judged at, and "converged" could be wrong: on the seed scene with cg-gamg and τ = 1e-6,
// linear_rtol = 1e-4 stopped "converged" at a true error of 8.3e-5, 0.5 at 0.12
// (docs/method.md §2, "Inexact linear solves").
LinearSolverOptions SolverSpec::linearAtTolerance() const {
  const double tau = tolerance(), loosest = LinearSolverOptions::kRtolPerTolerance * tau;
  if (linear.rtol > std::max(loosest, LinearSolverOptions::kRtolFloor))
    throw InputError("solver option linear_rtol = " + formatOption(linear.rtol) + ": must be 0 (the default, " +
                     formatOption(loosest) + ") or at most 1e-4 x solver.tolerance = " + formatOption(loosest) +
                     ": a looser linear solve can make \"converged\" wrong");
  LinearSolverOptions out = linear;
  out.rtol = linear.residualTolerance(tau);
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
