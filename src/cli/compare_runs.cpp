#include "src/cli/compare_runs.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>

#include "fas/solve_by_name.hpp"
#include "src/cli/progress.hpp"
#include "src/report/peak_memory.hpp"
#include "src/solver/condensed_interface.hpp"
#include "src/solver/incremental_solver.hpp"

namespace stc::cli {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// The exact solver: its solution is the reference, so it is reported as one point of error 0.
bool isReferenceSolver(const std::string& solver) { return solver == "incremental"; }

/// Strategies that take a converged solution as input (fas::StrategyInputs::converged_lambda).
bool needsConvergedSolution(const std::string& solver) { return solver == "fas-aposteriori"; }

struct RunOutcome {
  SolveResult result;
  std::vector<WorkPoint> points;  ///< one per history record, timed from the call
  double total_s = 0.0;
};

/// The history's records as points timed from the call: wall_s (from the solver's own start, after
/// its set-up) plus `setup_s`, the time from the call to that start.
std::vector<WorkPoint> pointsOf(const SolveSummary& summary, double setup_s) {
  std::vector<WorkPoint> points;
  for (const IterationRecord& r : summary.history)
    points.push_back({r.iteration, r.relaxations, r.sparse_solves, r.indicator, r.error, r.wall_s + setup_s});
  return points;
}

// The solvers call the callback after every record but the last (IterationMonitor stops first), so
// the set-up time is measured at the first callback: time since the call minus the record's wall_s.
// A run that stops at its first record never calls it: its set-up is bounded by the time outside
// the solver's clock (set-up and return).
RunOutcome runOnce(const std::string& solver, const CompareContext& c, bool measure_error, const std::string& label) {
  Progress progress(label, !c.quiet);
  const IterationCallback show = progress.callback();
  fas::StrategyInputs inputs;
  inputs.reference = measure_error ? c.reference.reference.get() : nullptr;
  inputs.converged_lambda = &c.reference.reference->referenceForces();
  std::optional<double> setup_s;
  const auto start = Clock::now();
  inputs.callback = [&](const IterationRecord& r) {
    if (!setup_s) setup_s = secondsSince(start) - r.wall_s;
    return show(r);
  };
  RunOutcome out;
  out.result = fas::solveByName(solver, c.problem, c.spec, inputs);
  out.total_s = secondsSince(start);
  progress.done();
  const SolveSummary& s = out.result.summary;
  out.points = pointsOf(s, setup_s.value_or(std::max(0.0, out.total_s - s.wall_s)));
  return out;
}

WorkPoint referencePoint(const RunOutcome& run, const ErrorReference& reference) {
  const SolveSummary& s = run.result.summary;
  WorkPoint p;
  p.iteration = s.iterations;
  p.sparse_solves = s.history.empty() ? 0 : s.history.back().sparse_solves;
  p.indicator = s.indicator;
  p.error = reference.relativeError(run.result.interface.lambda);
  p.wall_s = run.total_s;
  return p;
}

void describeResult(StrategyMeasurement& m, const SolveSummary& s) {
  m.termination = s.termination;
  m.message = s.message;
  m.iterations = s.iterations;
  m.relaxations = s.relaxations;
  m.indicator = s.indicator;
  m.final_error = s.error;
}

std::string repeatLabel(const std::string& solver, int repeat, int repeats) {
  return solver + " " + std::to_string(repeat) + "/" + std::to_string(repeats);
}

}  // namespace

ReferenceSolution computeReference(const Problem& problem, bool quiet) {
  ReferenceSolution out;
  Progress progress("reference (incremental)", !quiet);
  const auto start = Clock::now();
  SolveResult ref = solveIncremental(problem, {}, progress.callback());
  out.solve_s = secondsSince(start);
  progress.done();
  if (!ref.summary.converged())
    throw std::runtime_error("the incremental reference did not converge: " + ref.summary.message);
  const SpdFactor factor(problem.stiffness_free, "K_ff");
  const CondensedInterface condensed = CondensedInterface::build(problem, factor);
  out.reference = std::make_unique<ErrorReference>(problem, factor, condensed.delassus, ref.interface.lambda);
  out.total_s = secondsSince(start);
  return out;
}

StrategyMeasurement measureStrategy(const std::string& solver, const CompareContext& c) {
  StrategyMeasurement m;
  m.solver = solver;
  m.reference_point = isReferenceSolver(solver);
  if (needsConvergedSolution(solver)) m.prerequisite_s = c.reference.solve_s;
  PeakMemoryProbe probe;
  probe.reset();
  std::optional<RunOutcome> measured;
  if (!m.reference_point) {
    measured = runOnce(solver, c, true, solver + " (error run)");
    m.error_run_s = measured->total_s;
    describeResult(m, measured->result.summary);
  }
  for (int r = 1; r <= c.repeats; ++r) {
    RunOutcome timed = runOnce(solver, c, false, repeatLabel(solver, r, c.repeats));
    TimedRun run{r, {}, timed.total_s};
    if (m.reference_point) {
      run.points = {referencePoint(timed, *c.reference.reference)};
      if (r == 1) {
        describeResult(m, timed.result.summary);
        m.final_error = run.points.front().error;
      }
    } else {
      run.points = std::move(timed.points);
      if (!copyErrors(measured->points, run.points)) m.errors_matched = false;
    }
    m.runs.push_back(std::move(run));
  }
  m.memory = probe.sample();
  return m;
}

}  // namespace stc::cli
