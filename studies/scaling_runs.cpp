#include "stcontact/studies/scaling_runs.hpp"

#include "stcontact/studies/number_format.hpp"
#include "stcontact/studies/peak_memory.hpp"
#include "stcontact/studies/reference.hpp"
#include "stcontact/studies/run_environment.hpp"

namespace stc {
namespace {

std::string strategyLine(const ScalingStudy& study, const ScalingPoint& p, const StrategyMeasurement& m) {
  const Reach r = reachAt(study, p, m.solver);
  std::string line = "    " + m.solver + ": " +
                     (r.wall_s ? targetLabel(study.target_error) + " in " + shortNumber(*r.wall_s, 3) + " s"
                               : "not reached (" + reachStatus(study, p, m.solver) + ", best error " +
                                     shortNumber(m.best_error, 2) + ")") +
                     ", peak " + shortNumber(m.memory.peak_mb, 4) + " MB";
  if (m.error_run_s) line += ", error run " + shortNumber(*m.error_run_s, 3) + " s";
  return line;
}

/// Without the first-reach runs, the strategy's outcome and memory are its solve at tolerance's.
void atToleranceOnly(StrategyMeasurement& m, const SolveAtTolerance& a) {
  m.termination = a.termination;
  m.relaxations = a.relaxations;
  m.sparse_solves = a.sparse_solves;
  m.final_error_estimate = a.error_estimate;
  m.final_error = a.error;
  m.memory = a.memory;
}

void note(ProgressReporter* progress, const std::string& line) {
  if (progress) progress->note(line);
}

}  // namespace

ScalingPoint measureScalingSize(const Scene& scene, const ScalingSize& size, const ScalingStudy& study,
                                const EarlyStop& stop, ProgressReporter* progress) {
  const Problem problem = buildProblem(scene);
  ScalingPoint p;
  p.mesh_size = size.mesh_size;
  p.dimension = problem.contact.dimension;
  p.free_dofs = problem.numFreeDofs();
  p.in_mesh_series = size.in_mesh;
  p.in_time_series = size.in_time;
  p.comparison = describeComparison(study.scene_file, study.command, scene, problem, study.repeats);
  note(progress, "  " + std::to_string(p.comparison.n_dofs) + " dofs, " + std::to_string(p.comparison.n_contact_nodes) +
                     " contact nodes, " + std::to_string(p.comparison.n_steps) + " instants");
  const ReferenceSolution reference = computeReference(problem, progress);
  p.comparison.reference_s = reference.total_s;
  p.factor_nonzeros = reference.factor_nonzeros;
  note(progress, "    reference: " + shortNumber(reference.total_s, 3) + " s");
  CompareContext context{problem, scene.solver, reference, study.repeats, progress};
  context.stop = stop;
  std::vector<Strategy> strategies;
  for (const std::string& solver : study.solvers) {
    strategies.push_back(strategyNamed(solver));
    if (!study.first_reach) {
      p.comparison.strategies.push_back(StrategyMeasurement{});
      p.comparison.strategies.back().solver = solver;
      continue;
    }
    p.comparison.strategies.push_back(measureStrategy(strategies.back(), context));
    note(progress, strategyLine(study, p, p.comparison.strategies.back()));
  }
  // What a user gets: a solve at the target as tolerance, stopping on its own estimate.
  const std::vector<SolveAtTolerance> at = measureAtTolerance(strategies, context, study.target_error);
  for (std::size_t i = 0; i < at.size(); ++i) {
    StrategyMeasurement& m = p.comparison.strategies[i];
    m.at_tolerance = at[i];
    if (!study.first_reach) atToleranceOnly(m, at[i]);
    note(progress, "    " + study.solvers[i] + " at tolerance " + shortNumber(study.target_error, 3) + ": " +
                       toString(at[i].termination) + ", " + shortNumber(at[i].median_s, 3) + " s, true error " +
                       shortNumber(at[i].error, 2) + ", " + std::to_string(at[i].relaxations) + " relaxations, " +
                       std::to_string(at[i].sparse_solves) + " sparse solves, peak " +
                       shortNumber(at[i].memory.peak_mb, 4) + " MB");
  }
  p.comparison.memory_method = describeMemoryMethod(p.comparison.strategies.front().memory.since_reset);
  p.comparison.load_after = loadAverage();
  return p;
}

}  // namespace stc
