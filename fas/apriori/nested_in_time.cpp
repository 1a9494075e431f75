#include "stcontact/fas/apriori/nested_in_time.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "stcontact/fas/apriori/apriori_basis.hpp"
#include "stcontact/fas/fas_solver.hpp"
#include "stcontact/problem/time_subgrid.hpp"
#include "stcontact/spacetime/time_interpolation.hpp"

namespace stc {
namespace {

using Clock = std::chrono::steady_clock;

/// The sub-grid's tolerance is at least this: below it the start it gives stops improving, its
/// distance to the whole grid's solution is the time step's (seed scene at 401 arc nodes, 2001
/// instants, every 10th instant: true error of the start 4.4e-4, 1.0e-4, 9.5e-5 at sub-grid
/// tolerances 1e-3, 1e-4, 1e-5; docs/floor.md, "Long grids: nested iteration in time").
constexpr double kNestedTolerance = 1e-4;

// "2nd", "3rd", "10th", "11th", "21st".
std::string ordinal(int q) {
  const int last = q % 10, tens = q % 100;
  const char* suffix = (tens >= 11 && tens <= 13) ? "th" : last == 1 ? "st" : last == 2 ? "nd" : last == 3 ? "rd" : "th";
  return std::to_string(q) + suffix;
}

// What the sub-grid solve spent, added to the records of the solve on the whole grid.
struct SubgridCost {
  int instants = 0, stride = 0, relaxations = 0, sparse_solves = 0;
  double wall_s = 0.0;
  bool converged = false;

  IterationRecord added(IterationRecord r) const {
    r.sparse_solves += sparse_solves;
    r.wall_s += wall_s;
    return r;
  }
  std::string describe() const {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.3g s", wall_s);
    const std::string solve = "the solve on every " + ordinal(stride) + " instant (" + std::to_string(instants) +
                              " instants, " + std::to_string(relaxations) + " relaxations, " +
                              std::to_string(sparse_solves) + " sparse solves, " + seconds + ")";
    return converged ? "started from " + solve : solve + " did not converge: the whole grid solved from its own start";
  }
};

SolveResult solveFas(const Problem& problem, pgd::ControlledGlobalStage& stage, const SolverSpec& spec,
                     const InterfaceHistory& start, const ErrorMeasure* reference, const IterationCallback& callback) {
  fas::AprioriBasisProvider provider(stage, aprioriOptions(spec));
  return fas::solveFas(problem, stage, provider, start, fasOptions(spec), "fas-apriori", reference, callback);
}

InterfaceHistory atInstants(const InterfaceHistory& h, const std::vector<int>& kept) {
  return {h.v(Eigen::all, kept), h.lambda(Eigen::all, kept)};
}

}  // namespace

int nestedStride(int m, int coarse_instants) {
  if (coarse_instants < 2) return 0;
  const int q = (m - 1) / (coarse_instants - 1);
  return q >= 2 ? q : 0;
}

SolveResult solveFasNestedInTime(const Problem& problem, pgd::ControlledGlobalStage& stage, const SolverSpec& spec,
                                 const InterfaceHistory& start, const ErrorMeasure* reference,
                                 const IterationCallback& callback) {
  const int q = nestedStride(problem.numSteps(), spec.fas.nested_instants);
  if (q == 0) return solveFas(problem, stage, spec, start, reference, callback);
  const auto clock = Clock::now();
  const long solves_before = stage.sparseSolves();
  const std::vector<int> kept = everyNthInstant(problem.numSteps(), q);
  const Problem subgrid = onInstants(problem, kept);
  SolverSpec subgrid_spec = spec;
  subgrid_spec.tolerance = std::max(spec.tolerance, kNestedTolerance);
  stage.retime(subgrid);
  const SolveResult coarse = solveFas(subgrid, stage, subgrid_spec, atInstants(start, kept), nullptr, {});
  stage.retime(problem);
  SubgridCost cost{subgrid.numSteps(), q, coarse.summary.relaxations,
                   static_cast<int>(stage.sparseSolves() - solves_before), 0.0, coarse.summary.converged()};
  const InterfaceHistory interpolated =
      cost.converged ? interpolatedInTime(coarse.interface, subgrid.times, problem.times) : InterfaceHistory{};
  cost.wall_s = std::chrono::duration<double>(Clock::now() - clock).count();
  IterationCallback shifted;
  if (callback) shifted = [&](const IterationRecord& r) { return callback(cost.added(r)); };
  SolveResult out = solveFas(problem, stage, spec, cost.converged ? interpolated : start, reference, shifted);
  for (IterationRecord& r : out.summary.history) r = cost.added(r);
  out.summary.wall_s += cost.wall_s;
  out.summary.message += "; " + cost.describe();
  return out;
}

}  // namespace stc
