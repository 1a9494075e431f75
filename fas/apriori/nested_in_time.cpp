#include "stcontact/fas/apriori/nested_in_time.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "stcontact/core/interruption.hpp"
#include "stcontact/fas/apriori/apriori_basis.hpp"
#include "stcontact/fas/fas_solver.hpp"
#include "stcontact/problem/time_subgrid.hpp"
#include "stcontact/spacetime/time_interpolation.hpp"

namespace stc::fas {
namespace {

using Clock = std::chrono::steady_clock;

// "2nd", "3rd", "10th", "11th", "21st".
std::string ordinal(int q) {
  const int last = q % 10, tens = q % 100;
  const char* suffix = (tens >= 11 && tens <= 13) ? "th" : last == 1 ? "st" : last == 2 ? "nd" : last == 3 ? "rd" : "th";
  return std::to_string(q) + suffix;
}

// What the sub-grid solve spent: its stage in the summary (its sparse solves and time are in the
// records of the solve on the whole grid, through their origin).
struct SubgridCost {
  int instants = 0, stride = 0, relaxations = 0, sparse_solves = 0;
  double wall_s = 0.0;
  bool converged = false;

  SolveStage stage() const {
    return {SolveStage::Kind::SubGrid, describe(), relaxations, sparse_solves, wall_s, 0, 0};
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

SolveResult solveOnGrid(const Problem& problem, pgd::ControlledGlobalStage& stage, const FasAprioriOptions& options,
                        const SolveInputs& inputs, const SeparatedCoarseBasis& coarse_basis) {
  const std::unique_ptr<BasisProvider> provider = coarse_basis.providerOn(stage, problem, options.basis);
  return solveFas(problem, stage, *provider, options.fas, inputs, coarse_basis.solver);
}

InterfaceHistory atInstants(const InterfaceHistory& h, const std::vector<int>& kept) {
  return {h.v(Eigen::all, kept), h.lambda(Eigen::all, kept)};
}

}  // namespace

IterationCallback subgridProgress(NotedPhase& phase) {
  return [&phase](const IterationRecord& r) {
    char estimate[32];
    std::snprintf(estimate, sizeof estimate, "%.2e", r.error_estimate);
    phase.during("relaxation " + std::to_string(r.relaxations) + ", estimate " + estimate + ", " +
                 std::to_string(r.sparse_solves) + " sparse solves");
    return keepGoing();  // a caller's stop (src/core/interruption.hpp): the caller's callback sees no record here
  };
}

int nestedStride(int m, int coarse_instants, int max_stride) {
  if (coarse_instants < 2) return 0;
  int q = (m - 1) / (coarse_instants - 1);
  if (max_stride > 0) q = std::min(q, max_stride);
  return q >= 2 ? q : 0;
}

SolveResult solveFasNestedInTime(const Problem& problem, pgd::ControlledGlobalStage& stage,
                                 const FasAprioriOptions& options, const SolveInputs& inputs,
                                 const SeparatedCoarseBasis& coarse_basis) {
  const int q = options.nested.nestsOn(stage.factor().isDirect())
                    ? nestedStride(problem.numSteps(), options.nested.instants, options.nested.max_stride)
                    : 0;
  if (q == 0) return solveOnGrid(problem, stage, options, inputs, coarse_basis);
  const InterfaceHistory start = startingHistory(problem, inputs);
  const RecordOrigin origin = inputs.origin.clocked();
  const auto clock = Clock::now();
  const long solves_before = stage.sparseSolves();
  const std::vector<int> kept = everyNthInstant(problem.numSteps(), q);
  const Problem subgrid = onInstants(problem, kept);
  FasAprioriOptions subgrid_options = options;
  subgrid_options.fas.stop.tolerance = std::max(options.fas.stop.tolerance, options.nested.tolerance);
  stage.retime(subgrid);
  const InterfaceHistory subgrid_start = atInstants(start, kept);
  // Its own counts (no true error), on the whole solve's clock; its progress told as a phase.
  NotedPhase phase(inputs.phase_note, "on every " + ordinal(q) + " instant (" + std::to_string(subgrid.numSteps()) +
                                          " instants): ");
  const SolveInputs own{.callback = subgridProgress(phase),
                        .start = &subgrid_start,
                        .origin = {.clock = origin.clock, .krylov = origin.krylov}};
  const SolveResult coarse = solveOnGrid(subgrid, stage, subgrid_options, own, coarse_basis);
  // Only keepGoing() stops it (subgridProgress): the caller asked to stop.
  if (coarse.summary.termination == Termination::StoppedByCallback) throw Interrupted();
  stage.retime(problem);
  SubgridCost cost{subgrid.numSteps(), q, coarse.summary.relaxations,
                   static_cast<int>(stage.sparseSolves() - solves_before), 0.0, coarse.summary.converged()};
  const InterfaceHistory interpolated =
      cost.converged ? interpolatedInTime(coarse.interface, subgrid.times, problem.times) : InterfaceHistory{};
  cost.wall_s = std::chrono::duration<double>(Clock::now() - clock).count();
  SolveInputs whole = inputs;
  whole.start = cost.converged ? &interpolated : &start;
  whole.origin = origin.afterSolves(cost.sparse_solves);
  SolveResult out = solveOnGrid(problem, stage, options, whole, coarse_basis);
  out.summary.addStage(cost.stage());
  return out;
}

}  // namespace stc::fas
