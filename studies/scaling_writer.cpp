#include "stcontact/studies/scaling_writer.hpp"

#include <cmath>
#include <sstream>

#include "stcontact/io/atomic_file.hpp"
#include "stcontact/studies/comparison_writer.hpp"
#include "stcontact/studies/number_format.hpp"

namespace stc {
namespace {

std::string ratioCell(double ratio) { return std::isfinite(ratio) ? shortNumber(ratio, 4) : ""; }

// The solve at the target as tolerance: time, termination, relaxations, sparse solves, estimate, true
// error, time ÷ incremental's, Krylov iterations, peak memory, the incremental solver's form (empty
// cells when it was not run).
std::string atToleranceCells(const ScalingPoint& p, const StrategyMeasurement& m) {
  if (!m.at_tolerance) return ",,,,,,,,,";
  const SolveAtTolerance& a = *m.at_tolerance;
  std::ostringstream cells;
  cells << shortNumber(a.median_s, 6) << ',' << toString(a.termination) << ',' << a.relaxations << ','
        << a.sparse_solves << ',' << shortNumber(a.error_estimate, 4) << ',' << shortNumber(a.error, 4) << ','
        << ratioCell(p.timeRatioAtTolerance(m)) << ',' << a.krylov_iterations << ','
        << shortNumber(a.memory.peak_mb, 5) << ',' << a.incremental_form;
  return cells.str();
}

void csvHeader(std::ostream& out, const ScalingStudy& study) {
  out << "series," << study.mesh_parameter << ",dofs,free_dofs,contact_nodes,steps,solver,status,time_to_target_s,"
         "relaxations_to_target,sparse_solves_to_target,repeats_reaching,time_ratio_to_incremental,"
         "error_at_stop,best_error,iterations,peak_rss_mb,rss_growth_mb,baseline_mb,reference_s,error_run_s,"
         "factor_mb,interface_history_mb,displacement_history_mb,delassus_mb,condensation_mb,"
         "time_at_tolerance_s,termination_at_tolerance,relaxations_at_tolerance,sparse_solves_at_tolerance,"
         "error_estimate_at_tolerance,error_at_tolerance,time_ratio_at_tolerance,krylov_iterations_at_tolerance,"
         "peak_rss_mb_at_tolerance,incremental_form_at_tolerance\n";
}

void csvRow(std::ostream& out, const ScalingStudy& study, Series series, const ScalingPoint& p,
            const StrategyMeasurement& m) {
  const Comparison& c = p.comparison;
  const Reach r = reachAt(study, p, m.solver);
  const Reach ref = reachAt(study, p, "incremental");
  const double ratio = r.wall_s && ref.wall_s ? *r.wall_s / *ref.wall_s : NAN;
  const MemoryEstimate e = estimateMemory(p);
  out << toString(series) << ',' << p.mesh_size << ',' << c.n_dofs << ',' << p.free_dofs << ','
      << c.n_contact_nodes << ',' << c.n_steps << ',' << m.solver << ',' << reachStatus(study, p, m.solver) << ','
      << shortNumber(r.wall_s, 6) << ',' << shortNumber(r.relaxations, 8) << ',' << shortNumber(r.sparse_solves, 12)
      << ',' << r.repeats_reached << ',' << ratioCell(ratio) << ',' << shortNumber(m.final_error, 4) << ','
      << shortNumber(m.best_error, 4) << ',' << m.iterations << ',' << shortNumber(m.memory.peak_mb, 5) << ',' << shortNumber(m.memory.growthMb(), 4)
      << ',' << shortNumber(m.memory.baseline_mb, 5) << ',' << shortNumber(c.reference_s, 4) << ','
      << shortNumber(m.error_run_s, 4) << ',' << shortNumber(e.factor_mb, 4) << ','
      << shortNumber(e.interface_history_mb, 4) << ',' << shortNumber(e.displacement_history_mb, 4) << ','
      << shortNumber(e.delassus_mb, 4) << ',' << shortNumber(e.condensation_mb, 4) << ',' << atToleranceCells(p, m)
      << '\n';
}

}  // namespace

std::string sizeFolderName(const ScalingStudy& study, const ScalingPoint& point) {
  return study.mesh_parameter + "_" + std::to_string(point.mesh_size) + "_steps_" +
         std::to_string(point.comparison.n_steps);
}

std::string scalingCsv(const ScalingStudy& study) {
  std::ostringstream out;
  csvHeader(out, study);
  // By series, strategy, then size: each strategy's rows of a series are consecutive (one line per plot).
  for (Series series : {Series::Mesh, Series::Time})
    for (const std::string& solver : study.solvers)
      for (const ScalingPoint* p : seriesPoints(study, series))
        if (const StrategyMeasurement* m = p->strategy(solver)) csvRow(out, study, series, *p, *m);
  return out.str();
}

void writeScaling(const std::filesystem::path& dir, const ScalingStudy& study) {
  if (study.first_reach)  // the sizes' comparisons are the first-reach runs
    for (const ScalingPoint& p : study.points) {
      const std::filesystem::path folder = dir / "sizes" / sizeFolderName(study, p);
      std::filesystem::create_directories(folder);
      writeComparison(folder, p.comparison);
    }
  writeFileAtomically(dir / "scaling.csv", scalingCsv(study));
  writeFileAtomically(dir / "summary.md", scalingMarkdown(study));
}

}  // namespace stc
