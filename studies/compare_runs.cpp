#include "stcontact/studies/compare_runs.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "stcontact/core/input_error.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/strategies/registry.hpp"
#include "stcontact/studies/number_format.hpp"
#include "stcontact/studies/peak_memory.hpp"
#include "stcontact/studies/run_environment.hpp"

namespace stc {
namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// The exact solver: its solution is the reference, so it is reported as one point of error 0.
bool isReferenceSolver(Strategy strategy) { return strategy == Strategy::Incremental; }

/// Strategies that take a converged solution as input (SolveInputs::converged_lambda).
bool needsConvergedSolution(Strategy strategy) { return strategy == Strategy::FasAposteriori; }

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
// the solver's clock (set-up and return). `go_on`, when set, stops the run by returning false.
RunOutcome runOnce(Strategy strategy, const CompareContext& c, bool measure_error, const std::string& label,
                   const IterationCallback& go_on = {}) {
  const RunProgress progress(c.progress, label);
  SolveInputs inputs;
  inputs.reference = measure_error ? c.reference.reference.get() : nullptr;
  inputs.converged_lambda = &c.reference.reference->referenceForces();
  inputs.spatial_modes = false;  // not reported
  std::optional<double> setup_s;
  const auto start = Clock::now();
  inputs.callback = [&](const IterationRecord& r) {
    if (!setup_s) setup_s = secondsSince(start) - r.wall_s;
    const bool shown = progress.show(r);
    return shown && (!go_on || go_on(r)) && (!c.keep_going || c.keep_going(r));
  };
  RunOutcome out;
  out.result = solve(strategy, c.problem, c.spec, inputs);
  out.total_s = secondsSince(start);
  const SolveSummary& s = out.result.summary;
  out.points = pointsOf(s, setup_s.value_or(std::max(0.0, out.total_s - s.wall_s)));
  return out;
}

/// The EarlyStop test of an error run: false (stop) at the first record that reaches the target, or
/// once the solver's clock passes the cap; `why` then says which, for the report.
IterationCallback errorRunStop(const EarlyStop& stop, std::string& why) {
  if (!stop.target_error && !stop.time_cap_s) return {};
  return [&stop, &why](const IterationRecord& r) {
    if (stop.target_error && r.error && *r.error <= *stop.target_error) {
      why = "stopped at iteration " + std::to_string(r.iteration) + ", the first with true error <= " +
            shortNumber(*stop.target_error, 3);
      return false;
    }
    if (stop.time_cap_s && r.wall_s >= *stop.time_cap_s) {
      why = "time cap of " + shortNumber(*stop.time_cap_s, 3) + " s reached at iteration " +
            std::to_string(r.iteration) + " (true error " + shortNumber(r.error, 3) + ")";
      return false;
    }
    return true;
  };
}

/// With a target error, the timed runs stop where the error run did; without one, they run to the end.
IterationCallback timedRunStop(const EarlyStop& stop, int last_iteration) {
  if (!stop.target_error) return {};
  return [last_iteration](const IterationRecord& r) { return r.iteration < last_iteration; };
}

WorkPoint referencePoint(const RunOutcome& run, const ErrorReference& reference) {
  const SolveSummary& s = run.result.summary;
  WorkPoint p;
  p.iteration = s.iterations;
  p.sparse_solves = s.sparseSolves();
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
  m.final_error_estimate = s.error_estimate;
  m.sparse_solves = s.sparseSolves();
  m.final_error = s.error;
}

std::optional<double> smallestError(const std::vector<WorkPoint>& points) {
  std::optional<double> best;
  for (const WorkPoint& p : points)
    if (p.error && (!best || *p.error < *best)) best = p.error;
  return best;
}

std::string repeatLabel(const std::string& solver, int repeat, int repeats) {
  return solver + " " + std::to_string(repeat) + "/" + std::to_string(repeats);
}

}  // namespace

StrategyMeasurement measureStrategy(Strategy strategy, const CompareContext& c) {
  StrategyMeasurement m;
  const std::string solver(nameOf(strategy));
  m.solver = solver;
  m.reference_point = isReferenceSolver(strategy);
  if (needsConvergedSolution(strategy)) m.prerequisite_s = c.reference.solve_s;
  PeakMemoryProbe probe;
  probe.reset();
  std::optional<RunOutcome> measured;
  IterationCallback timed_stop;
  if (!m.reference_point) {
    std::string why;
    measured = runOnce(strategy, c, true, solver + " (error run)", errorRunStop(c.stop, why));
    m.error_run_s = measured->total_s;
    describeResult(m, measured->result.summary);
    m.best_error = smallestError(measured->points);
    if (!why.empty()) m.message = why;
    timed_stop = timedRunStop(c.stop, m.iterations);
  }
  const bool nothing_to_time = measured && c.stop.target_error && !firstReaching(measured->points, *c.stop.target_error);
  // The peak is the timed runs' when there are any: they are the strategy alone, without the error
  // measure of the error run (whose Delassus columns may be computed during it).
  if (measured && !nothing_to_time && c.repeats > 0) probe.reset();
  for (int r = 1; r <= c.repeats && !nothing_to_time; ++r) {
    RunOutcome timed = runOnce(strategy, c, false, repeatLabel(solver, r, c.repeats), timed_stop);
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

std::vector<SolveAtTolerance> measureAtTolerance(const std::vector<Strategy>& strategies, const CompareContext& context,
                                                 double tolerance) {
  SolverSpec spec = context.spec;
  spec.setTolerance(tolerance);
  CompareContext at{context.problem, spec, context.reference, context.repeats, context.progress};
  at.keep_going = context.keep_going;
  std::vector<SolveAtTolerance> out(strategies.size());
  const int rounds = std::max(1, context.repeats);
  for (int r = 1; r <= rounds; ++r)
    for (std::size_t i = 0; i < strategies.size(); ++i) {
      const std::string solver(nameOf(strategies[i]));
      PeakMemoryProbe probe;
      probe.reset();
      const RunOutcome run = runOnce(strategies[i], at, false, repeatLabel(solver + " at tolerance", r, rounds));
      SolveAtTolerance& a = out[i];
      a.times_s.push_back(run.total_s);
      const MemoryUse memory = probe.sample();
      if (r == 1 || memory.peak_mb > a.memory.peak_mb) a.memory = memory;
      if (r > 1) continue;
      const SolveSummary& s = run.result.summary;
      a.tolerance = tolerance;
      a.termination = s.termination;
      a.relaxations = s.relaxations;
      a.sparse_solves = s.sparseSolves();
      a.krylov_iterations = s.krylov_iterations;
      a.incremental_form = s.incremental_form;
      a.error_estimate = s.error_estimate;
      a.error = context.reference.reference->relativeError(run.result.interface.lambda);
    }
  for (SolveAtTolerance& a : out) a.median_s = median(a.times_s);
  return out;
}

// Split here rather than by CLI11's ->delimiter(','): CLI11 2.1.2 (Debian 12) drops empty items, so
// "--solvers latin,,incremental" would pass as two names instead of the documented refusal
// "--solvers: empty name" (docs/compare.md; the ctest case cli.compare_empty_solver_name).
std::vector<Strategy> solverList(const std::optional<std::string>& given) {
  std::vector<Strategy> strategies;
  if (!given) {
    for (const auto& [name, strategy] : kStrategies) strategies.push_back(strategy);
    return strategies;
  }
  const std::string& list = *given;
  if (trimmed(list).empty())
    throw InputError("--solvers: the list is empty (leave the option out to run every strategy)");
  if (trimmed(list).back() == ',') throw InputError("--solvers: empty name in '" + list + "'");  // getline drops it
  std::stringstream items(list);
  std::string item;
  while (std::getline(items, item, ',')) {
    const std::string name = trimmed(item);
    if (name.empty()) throw InputError("--solvers: empty name in '" + list + "'");
    const Strategy strategy = strategyNamed(name);
    if (std::find(strategies.begin(), strategies.end(), strategy) != strategies.end())
      throw InputError("--solvers: '" + name + "' is listed twice");
    strategies.push_back(strategy);
  }
  return strategies;
}

Comparison describeComparison(const std::string& scene_file, const std::string& command, const Scene& scene,
                              const Problem& problem, int repeats) {
  Comparison c;
  c.scene_name = scene.name;
  c.scene_file = scene_file;
  c.command = command;
  c.n_dofs = problem.numDofs();
  c.n_contact_nodes = problem.contact.size();
  c.n_steps = problem.numSteps();
  c.tolerance = scene.solver.tolerance();
  c.repeats = repeats;
  c.environment = describeRunEnvironment();
  return c;
}

}  // namespace stc
