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
    p.comparison.strategies.push_back(measureStrategy(strategies.back(), context));
    note(progress, strategyLine(study, p, p.comparison.strategies.back()));
  }
  // What a user gets: a solve at the target as tolerance, stopping on its own estimate.
  const std::vector<SolveAtTolerance> at = measureAtTolerance(strategies, context, study.target_error);
  for (std::size_t i = 0; i < at.size(); ++i) {
    p.comparison.strategies[i].at_tolerance = at[i];
    note(progress, "    " + study.solvers[i] + " at tolerance " + shortNumber(study.target_error, 3) + ": " +
                       toString(at[i].termination) + ", " + shortNumber(at[i].median_s, 3) + " s, true error " +
                       shortNumber(at[i].error, 2));
  }
  p.comparison.memory_method = describeMemoryMethod(p.comparison.strategies.front().memory.since_reset);
  p.comparison.load_after = loadAverage();
  return p;
}

}  // namespace stc
