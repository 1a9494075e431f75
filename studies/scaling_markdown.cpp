// summary.md of a scaling study (declared in scaling_writer.hpp).
#include <cmath>
#include <sstream>

#include "stcontact/studies/comparison_writer.hpp"
#include "stcontact/studies/number_format.hpp"
#include "stcontact/studies/run_environment.hpp"
#include "stcontact/studies/scaling_writer.hpp"

namespace stc {
namespace {

std::string separator(std::size_t columns) {
  std::string line = "|";
  for (std::size_t i = 0; i < columns; ++i) line += "---|";
  return line + "\n";
}

std::string sizeName(Series series) { return series == Series::Mesh ? "dofs" : "m"; }

std::string solverColumns(const ScalingStudy& s) {
  std::string header;
  for (const auto& solver : s.solvers) header += " " + solver + " |";
  return header;
}

void introduction(std::ostream& out, const ScalingStudy& s) {
  const std::string target = targetLabel(s.target_error);
  out << "# Scaling study: " << s.scene_name << "\n\n"
      << "Produced by `" << s.command << "` in " << shortNumber(s.run_s, 3) << " s.\n\n"
      << "Scene `" << s.scene_file << "`. At each size every strategy is first solved as a user runs it, at "
      << "tolerance " << target << " on its own error estimate (the first table of each series: its wall time, "
      << "from the call, and its true error at termination). ";
  if (!s.first_reach) {
    out << "Only these solves are run (`--only-at-tolerance`): the exponents, the crossovers and the plots are "
           "on their median times, over "
        << s.repeats << " repeat(s), of the runs that converged on their estimate. The true error is against "
        << "the incremental solution at a tight tolerance (docs/method.md §2), computed once per size and not "
           "timed.\n\n";
    return;
  }
  out << "Then, as a diagnostic, each size is a `stcontact "
      << "compare` of the strategies (its report: "
      << "`sizes/<size>/summary.md`), with every iterative run stopped at the first iteration whose true error "
      << "(relative energy over the space-time grid against the incremental solution, docs/method.md §2) is at most "
      << target << ": the times below are medians over " << s.repeats << " timed repeat(s) of the time from the "
      << "call to the solver (set-up included) to that iteration. Indicator tolerance "
      << shortNumber(s.tolerance, 3) << "; "
      << (s.time_cap_s ? "time cap " + shortNumber(*s.time_cap_s, 4) + " s per error run" : "no time cap")
      << ". The incremental solver is exact: its time is its whole solve.\n\n";
}

std::string reachCell(const ScalingStudy& s, const ScalingPoint& p, const std::string& solver) {
  const Reach r = reachAt(s, p, solver);
  if (r.wall_s) return shortNumber(*r.wall_s, 3) + " s";
  const StrategyMeasurement* m = p.strategy(solver);
  const std::string best = m && m->best_error ? "; best error " + shortNumber(*m->best_error, 2) : "";
  return "not reached (" + reachStatus(s, p, solver) + best + ")";
}

std::string workCell(const ScalingStudy& s, const ScalingPoint& p, const std::string& solver) {
  const Reach r = reachAt(s, p, solver);
  if (!r.wall_s) return "—";
  return shortNumber(r.relaxations, 8) + " / " + shortNumber(r.sparse_solves, 10);
}

// "arc nodes" / "divisions": the mesh series' column.
std::string meshColumn(const ScalingStudy& s) {
  return s.mesh_parameter == "arc_nodes" ? "arc nodes" : s.mesh_parameter;
}

// "101 arc nodes" / "divisions 8".
std::string meshSizeLabel(const ScalingStudy& s, const ScalingPoint& p) {
  return s.mesh_parameter == "arc_nodes" ? std::to_string(p.mesh_size) + " arc nodes"
                                         : s.mesh_parameter + " " + std::to_string(p.mesh_size);
}

// "0.72 s (3.0 ×), converged, error 2.7e-07": the solve at the target as tolerance, its time against
// the incremental solver's at the same size.
std::string atToleranceCell(const ScalingPoint& p, const std::string& solver) {
  const StrategyMeasurement* m = p.strategy(solver);
  if (!m || !m->at_tolerance) return "—";
  const SolveAtTolerance& a = *m->at_tolerance;
  std::string cell = shortNumber(a.median_s, 3) + " s";
  if (solver == "incremental") return cell;
  const double ratio = p.timeRatioAtTolerance(*m);
  if (std::isfinite(ratio)) cell += " (" + shortNumber(ratio, 3) + " ×)";
  return cell + ", " + toString(a.termination) + ", error " + shortNumber(a.error, 2);
}

void atToleranceTable(std::ostream& out, const ScalingStudy& s, const std::vector<const ScalingPoint*>& points) {
  out << "\nA solve at tolerance " << shortNumber(s.target_error, 3) << " (what `stcontact solve --tol "
      << shortNumber(s.target_error, 3) << "` gives: each run stops on its own estimate), median of " << s.repeats
      << " repeat(s), the strategies alternated; in parentheses the time ÷ incremental's, then the termination and "
         "the true error at termination:\n\n"
      << "| " << meshColumn(s) << " | dofs | n_C | m |" << solverColumns(s) << "\n" << separator(4 + s.solvers.size());
  for (const ScalingPoint* p : points) {
    out << "| " << p->mesh_size << " | " << p->comparison.n_dofs << " | " << p->comparison.n_contact_nodes << " | "
        << p->comparison.n_steps << " |";
    for (const auto& solver : s.solvers) out << " " << atToleranceCell(*p, solver) << " |";
    out << "\n";
  }
}

// "21 / 106 / 0 / 812 MB": relaxations, sparse solves, Krylov iterations, peak memory of the solve at
// tolerance; the incremental solver's form after it, "0 / 96 / 0 / 711 MB (interface)".
std::string atToleranceWorkCell(const ScalingPoint& p, const std::string& solver) {
  const StrategyMeasurement* m = p.strategy(solver);
  if (!m || !m->at_tolerance) return "—";
  const SolveAtTolerance& a = *m->at_tolerance;
  return std::to_string(a.relaxations) + " / " + std::to_string(a.sparse_solves) + " / " +
         std::to_string(a.krylov_iterations) + " / " + shortNumber(a.memory.peak_mb, 4) + " MB" +
         (a.incremental_form.empty() ? "" : " (" + a.incremental_form + ")");
}

void atToleranceWorkTable(std::ostream& out, const ScalingStudy& s, Series series,
                          const std::vector<const ScalingPoint*>& points) {
  out << "\nRelaxations / sparse solves / Krylov iterations / peak resident memory of the first solve at "
         "tolerance (the largest peak over the repeats), the incremental solver's form in brackets:\n\n| "
      << sizeName(series) << " |" << solverColumns(s) << "\n" << separator(1 + s.solvers.size());
  for (const ScalingPoint* p : points) {
    out << "| " << p->size(series) << " |";
    for (const auto& solver : s.solvers) out << " " << atToleranceWorkCell(*p, solver) << " |";
    out << "\n";
  }
  out << "\n";
}

void seriesTables(std::ostream& out, const ScalingStudy& s, Series series) {
  const auto points = seriesPoints(s, series);
  if (points.empty()) return;
  const ScalingPoint& first = *points.front();
  out << "## " << (series == Series::Mesh ? "Mesh series (m = " + std::to_string(first.comparison.n_steps) + ")"
                                          : "Time series (" + meshSizeLabel(s, first) + ", " +
                                                std::to_string(first.comparison.n_dofs) + " dofs)")
      << "\n";
  atToleranceTable(out, s, points);
  if (!s.first_reach) {
    atToleranceWorkTable(out, s, series, points);
    return;
  }
  out << "\nTime to first reach " << targetLabel(s.target_error)
      << " (a diagnostic: stopping there needs the reference):\n\n"
      << "| " << meshColumn(s) << " | dofs | n_C | m |" << solverColumns(s) << "\n" << separator(4 + s.solvers.size());
  for (const ScalingPoint* p : points) {
    out << "| " << p->mesh_size << " | " << p->comparison.n_dofs << " | " << p->comparison.n_contact_nodes << " | "
        << p->comparison.n_steps << " |";
    for (const auto& solver : s.solvers) out << " " << reachCell(s, *p, solver) << " |";
    out << "\n";
  }
  out << "\nRelaxations / sparse solves to reach it:\n\n| " << sizeName(series) << " |" << solverColumns(s) << "\n"
      << separator(1 + s.solvers.size());
  for (const ScalingPoint* p : points) {
    out << "| " << p->size(series) << " |";
    for (const auto& solver : s.solvers) out << " " << workCell(s, *p, solver) << " |";
    out << "\n";
  }
  out << "\n";
}

/// "1.23 ± 0.05 (3 sizes)", "2.95 (2 sizes: no error estimate)", "— (reached at 1 of 3 sizes)".
std::string exponentCell(const SeriesFit& f) {
  const std::string sizes = f.sizes_reached == f.sizes ? std::to_string(f.sizes) + " sizes"
                                                       : std::to_string(f.sizes_reached) + " of " +
                                                             std::to_string(f.sizes) + " sizes reached";
  if (!f.fit) return "— (" + sizes + ")";
  if (!std::isfinite(f.fit->exponent_stderr)) return shortNumber(f.fit->exponent, 3) + " (" + sizes + ": no error estimate)";
  return shortNumber(f.fit->exponent, 3) + " ± " + shortNumber(f.fit->exponent_stderr, 2) + " (" + sizes + ")";
}

// What the fits and ratios are on: "Time to 1e-4" or "Time of the solve at tolerance 1e-4".
std::string fittedTimeName(const ScalingStudy& s) {
  return (s.first_reach ? "Time to " : "Time of the solve at tolerance ") + targetLabel(s.target_error);
}

void exponentTable(std::ostream& out, const ScalingStudy& s) {
  out << "## Growth exponents\n\n" << fittedTimeName(s)
      << " fitted as t = C · size^p by least squares on log-log axes (GSL `gsl_fit_linear` on log t against "
         "log size); ± is the standard error of p from the scatter about the line (n − 2 degrees of freedom), "
         "undefined for two sizes. Only sizes where the target was reached (at tolerance: where the solve "
         "converged) enter the fit.\n\n"
      << "| strategy | mesh series: p against dofs | time series: p against m |\n" << separator(3);
  for (const auto& solver : s.solvers)
    out << "| " << solver << " | " << exponentCell(fitSeries(s, solver, Series::Mesh)) << " | "
        << exponentCell(fitSeries(s, solver, Series::Time)) << " |\n";
  out << "\n";
}

std::string crossingText(const Crossover& c, Series series, double largest) {
  if (c.first_faster) return "faster from " + sizeName(series) + " = " + shortNumber(*c.first_faster, 6);
  if (!c.fitted_crossing) return "never faster; no fit to extrapolate (fewer than two sizes reached)";
  if (!c.faster_beyond) return "never faster; the fitted lines diverge (larger exponent): no crossover beyond the sizes";
  const std::string at = sizeName(series) + " ≈ " + shortNumber(*c.fitted_crossing, 3);
  return *c.fitted_crossing > largest ? "never faster in range; the fitted lines cross at " + at + " (extrapolated)"
                                      : "never faster; the fitted lines cross at " + at + ", inside the range (scatter)";
}

void crossoverTable(std::ostream& out, const ScalingStudy& s, Series series) {
  const auto points = seriesPoints(s, series);
  if (points.empty() || !points.front()->strategy("incremental")) return;
  out << "### " << (series == Series::Mesh ? "Mesh series" : "Time series") << "\n\n| strategy |";
  for (const ScalingPoint* p : points) out << " " << sizeName(series) << " = " << p->size(series) << " |";
  out << " crossover |\n" << separator(2 + points.size());
  for (const auto& solver : s.solvers) {
    if (solver == "incremental") continue;
    const Crossover c = crossoverAgainstIncremental(s, solver, series);
    out << "| " << solver << " |";
    for (double r : c.time_ratio) out << " " << (std::isfinite(r) ? shortNumber(r, 3) : "—") << " |";
    out << " " << crossingText(c, series, points.back()->size(series)) << " |\n";
  }
  out << "\n";
}

void crossoverSection(std::ostream& out, const ScalingStudy& s) {
  out << "## Against the incremental solver\n\n" << fittedTimeName(s)
      << " over the incremental solver's (below 1: faster), and where the strategy becomes the faster one: the "
         "first size measured, else the crossing of the two fitted power laws.\n\n";
  crossoverTable(out, s, Series::Mesh);
  crossoverTable(out, s, Series::Time);
}

void memoryTable(std::ostream& out, const ScalingStudy& s) {
  out << "| " << meshColumn(s) << " | m | baseline |" << solverColumns(s) << "\n" << separator(3 + s.solvers.size());
  for (const ScalingPoint& p : s.points) {
    const StrategyMeasurement* any = p.comparison.strategies.empty() ? nullptr : &p.comparison.strategies.front();
    out << "| " << p.mesh_size << " | " << p.comparison.n_steps << " | "
        << (any ? shortNumber(any->memory.baseline_mb, 4) : "—") << " |";
    for (const auto& solver : s.solvers) {
      const StrategyMeasurement* m = p.strategy(solver);
      out << " " << (m ? shortNumber(m->memory.peak_mb, 4) + " (" + shortNumber(m->memory.growthMb(), 3) + ")" : "—")
          << " |";
    }
    out << "\n";
  }
}

void estimateTable(std::ostream& out, const ScalingStudy& s) {
  out << "\nWhat the sizes predict, in MB of 8-byte doubles: the Cholesky factor of K_ff (K + BᵀkB has the same "
         "pattern), one interface history (d n_C × m, d rows per contact node: the LATIN iterates s, ŝ are a few "
         "of them), one displacement history (n_free × m), the dense Delassus matrix W = B K⁻¹ Bᵀ (d n_C)² that "
         "the 2D incremental solver holds (in 3D it keeps the columns of the nodes that close, and the error "
         "measure those of the nodes an iterate loads), the dense Bᵀ and K⁻¹ Bᵀ (n_free × d n_C each) it is "
         "formed from, one dense m × m matrix.\n\n"
      << "| " << meshColumn(s) << " | m | n_free | n_C | factor | interface history | displacement history | Delassus | "
         "Bᵀ and K⁻¹Bᵀ | m × m |\n"
      << separator(10);
  for (const ScalingPoint& p : s.points) {
    const MemoryEstimate e = estimateMemory(p);
    out << "| " << p.mesh_size << " | " << p.comparison.n_steps << " | " << p.free_dofs << " | "
        << p.comparison.n_contact_nodes << " | " << shortNumber(e.factor_mb, 3) << " | "
        << shortNumber(e.interface_history_mb, 3) << " | " << shortNumber(e.displacement_history_mb, 3) << " | "
        << shortNumber(e.delassus_mb, 3) << " | " << shortNumber(e.condensation_mb, 3) << " | "
        << shortNumber(e.time_matrix_mb, 3) << " |\n";
  }
}

void slopeTable(std::ostream& out, const ScalingStudy& s) {
  out << "\nGrowth per instant along the time series: (growth at m₁ − growth at m₀) / (m₁ − m₀), in kB, and "
         "the same in interface-history columns (d n_C doubles) and in displacement fields (n_free doubles). "
         "A claim that only interface histories and low-rank factors grow with m means a few interface "
         "columns per instant, far below one displacement field; a rate that rises with m means m × m storage."
         "\n\n| strategy | m₀ → m₁: kB per instant = interface columns = displacement fields |\n"
      << separator(2);
  for (const auto& solver : s.solvers) {
    out << "| " << solver << " |";
    for (const MemorySlope& m : memorySlopes(s, solver))
      out << " " << m.m_from << " → " << m.m_to << ": " << shortNumber(m.bytes_per_instant / 1024.0, 3) << " = "
          << shortNumber(m.interface_arrays, 3) << " = " << shortNumber(m.free_dof_fields, 2) << ";";
    out << " |\n";
  }
}

void memorySection(std::ostream& out, const ScalingStudy& s) {
  out << "## Peak resident memory\n\nPeak (MB) of each strategy's runs at each size, and in parentheses its "
         "growth over the resident size before them (the baseline: the problem and the incremental reference). "
      << (s.first_reach ? "Runs stop at the target error, so this is the memory needed to reach it. "
                        : "Runs are the solves at tolerance. ")
      << "How: "
      << s.memory_method << ".\n\n";
  memoryTable(out, s);
  estimateTable(out, s);
  slopeTable(out, s);
  out << "\n";
}

void notReachedNotes(std::ostream& out, const ScalingStudy& s) {
  if (!s.first_reach) return;  // the at-tolerance table says how each solve ended
  std::ostringstream notes;
  for (const ScalingPoint& p : s.points)
    for (const StrategyMeasurement& m : p.comparison.strategies)
      if (!reachAt(s, p, m.solver).wall_s)
        notes << "- " << m.solver << " at " << meshSizeLabel(s, p) << ", m = " << p.comparison.n_steps << ": "
              << m.message << " (" << m.iterations << " iterations, " << m.relaxations << " relaxations, error run "
              << shortNumber(m.error_run_s, 3) << " s; final true error " << shortNumber(m.final_error, 2)
              << ", best " << shortNumber(m.best_error, 2) << ").\n";
  if (notes.str().empty()) return;
  out << "## Targets not reached\n\nWhy each run without a time ended (the solver's message of its error run):\n\n"
      << notes.str() << "\n";
}

}  // namespace

std::string scalingMarkdown(const ScalingStudy& study) {
  std::ostringstream out;
  introduction(out, study);
  seriesTables(out, study, Series::Mesh);
  seriesTables(out, study, Series::Time);
  exponentTable(out, study);
  crossoverSection(out, study);
  memorySection(out, study);
  notReachedNotes(out, study);
  out << machineMarkdown(study.environment, study.load_after);
  return out.str();
}

}  // namespace stc
