// summary.md of a comparison (declared in comparison_writer.hpp).
#include <cmath>
#include <sstream>

#include "stcontact/studies/comparison_writer.hpp"
#include "stcontact/studies/number_format.hpp"

namespace stc {
namespace {

std::string seconds(const std::optional<double>& s) { return s ? shortNumber(*s, 3) + " s" : "not reached"; }

std::string label(const StrategyMeasurement& m) { return m.reference_point ? m.solver + " (reference)" : m.solver; }

/// "1.2 s", or "1.2 s (2 of 3 repeats)" when some repeats did not reach the target.
std::string reachTime(const Reach& r, int repeats) {
  std::string text = seconds(r.wall_s);
  if (r.wall_s && r.repeats_reached < repeats)
    text += " (" + std::to_string(r.repeats_reached) + " of " + std::to_string(repeats) + " repeats)";
  return text;
}

std::string targetColumns(const std::string& prefix) {
  std::string header;
  for (double t : targetErrors()) header += " " + prefix + targetLabel(t) + " |";
  return header;
}

std::string separator(int columns) {
  std::string line = "|";
  for (int i = 0; i < columns; ++i) line += "---|";
  return line + "\n";
}

std::string finalError(const StrategyMeasurement& m) {
  if (m.reference_point) return "0 (the reference)";
  return m.final_error ? shortNumber(*m.final_error, 2) : "unknown";
}

void introduction(std::ostream& out, const Comparison& c) {
  out << "# Work against precision: " << c.scene_name << "\n\n"
      << "Produced by `" << c.command << "`.\n\n"
      << "Scene `" << c.scene_file << "`: " << c.n_dofs << " dofs, " << c.n_contact_nodes << " contact nodes, "
      << c.n_steps << " instants; tolerance on the error estimate " << shortNumber(c.tolerance, 3) << "; " << c.repeats
      << " timed repeats per strategy, medians over them.\n\n"
      << "True error: relative elastic energy over the space-time grid against the incremental solution "
         "(docs/method.md §2). Times are seconds since the solver was called, set-up (factorisations, bases) "
         "included, measured in runs that do not evaluate the true error; the error at each iteration comes "
         "from one more run of the same deterministic solver that does evaluate it (its time: \"error run\" "
         "below, not counted). Incremental reference and error measure: "
      << shortNumber(c.reference_s, 3) << " s, not counted.\n\n";
}

std::string estimate(const StrategyMeasurement& m) {
  if (m.reference_point) return "·";
  return std::isfinite(m.final_error_estimate) ? shortNumber(m.final_error_estimate, 2) : "none";
}

/// What `stcontact solve --tol` gives: the timed runs stop on the strategy's own estimate.
void toleranceTable(std::ostream& out, const Comparison& c, const std::vector<StrategySummary>& all) {
  out << "## A solve at tolerance " << shortNumber(c.tolerance, 3) << " (what `stcontact solve --tol "
      << shortNumber(c.tolerance, 3) << "` gives)\n\n"
      << "Each run stops on its own error estimate; the true error is the one at termination.\n\n"
      << "| strategy | termination | relaxations | sparse solves | error estimate | true error | wall time | ÷ incremental |\n"
      << separator(8);
  const StrategySummary* incremental = findSummary(all, "incremental");
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto& m = c.strategies[i];
    const bool ratio = incremental && incremental->median_total_s > 0.0 && all[i].repeats > 0;
    out << "| " << label(m) << " | " << toString(m.termination) << " | " << m.relaxations << " | " << m.sparse_solves
        << " | " << estimate(m) << " | " << finalError(m) << " | " << shortNumber(all[i].median_total_s, 3) << " s | "
        << (ratio ? shortNumber(all[i].median_total_s / incremental->median_total_s, 3) : "—") << " |\n";
  }
  out << "\n";
}

void timeTable(std::ostream& out, const Comparison& c, const std::vector<StrategySummary>& all) {
  out << "## Time to first reach a true error (a diagnostic: stopping there needs the reference)\n\n| strategy |"
      << targetColumns("")
      << " final error | termination | whole solve |\n" << separator(7);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto& m = c.strategies[i];
    out << "| " << label(m) << " |";
    for (const Reach& r : all[i].reaches) out << " " << reachTime(r, all[i].repeats) << " |";
    out << " " << finalError(m) << " | " << toString(m.termination) << " (" << m.iterations << " iterations) | "
        << shortNumber(all[i].median_total_s, 3) << " s |\n";
  }
  out << "\n";
}

void workTable(std::ostream& out, const Comparison& c, const std::vector<StrategySummary>& all) {
  out << "## Relaxations / sparse solves to first reach a true error\n\n| strategy |" << targetColumns("")
      << "\n" << separator(4);
  for (std::size_t i = 0; i < all.size(); ++i) {
    out << "| " << label(c.strategies[i]) << " |";
    for (const Reach& r : all[i].reaches)
      out << " " << (r.wall_s ? shortNumber(r.relaxations, 8) + " / " + shortNumber(r.sparse_solves, 10) : "—")
          << " |";
    out << "\n";
  }
  out << "\n";
}

void ratioTable(std::ostream& out, const Comparison& c, const std::vector<StrategySummary>& all) {
  out << "## Time ratios (this strategy's median time over the other's: below 1 is faster)\n\n| strategy |"
      << targetColumns("÷ latin, ") << targetColumns("÷ incremental, ") << "\n" << separator(7);
  for (std::size_t i = 0; i < all.size(); ++i) {
    out << "| " << label(c.strategies[i]) << " |";
    for (const char* other : {"latin", "incremental"})
      for (std::size_t t = 0; t < targetErrors().size(); ++t) {
        const auto ratio = timeRatioTo(all, all[i], other, t);
        out << " " << (ratio ? shortNumber(*ratio, 3) : "—") << " |";
      }
    out << "\n";
  }
  out << "\n";
}

void memoryTable(std::ostream& out, const Comparison& c) {
  out << "## Peak resident memory\n\n| strategy | peak (MB) | growth over the baseline (MB) | baseline (MB) |\n"
      << separator(4);
  for (const auto& m : c.strategies)
    out << "| " << label(m) << " | " << shortNumber(m.memory.peak_mb, 4) << " | " << shortNumber(m.memory.growthMb(), 3)
        << " | " << shortNumber(m.memory.baseline_mb, 4) << " |\n";
  out << "\nHow: " << c.memory_method << ".\n\n";
}

void notes(std::ostream& out, const Comparison& c) {
  out << "## Notes\n\n";
  for (const auto& m : c.strategies) {
    if (m.error_run_s) out << "- " << m.solver << ": error run " << shortNumber(*m.error_run_s, 3) << " s.\n";
    if (m.prerequisite_s)
      out << "- " << m.solver << " needs a converged solution: the comparison gives it the reference's, whose "
          << "incremental solve (" << shortNumber(*m.prerequisite_s, 3) << " s) is not in its times.\n";
    if (!m.errors_matched)
      out << "- " << m.solver << ": a timed run did not repeat the error run's iterations; its unmatched "
          << "points have no error and may be missing from the times above.\n";
    if (!m.message.empty()) out << "- " << m.solver << ": " << m.message << "\n";
  }
  out << "\n";
}

}  // namespace

std::string summaryMarkdown(const Comparison& comparison) {
  const std::vector<StrategySummary> all = summarizeAll(comparison);
  std::ostringstream out;
  introduction(out, comparison);
  toleranceTable(out, comparison, all);
  timeTable(out, comparison, all);
  workTable(out, comparison, all);
  ratioTable(out, comparison, all);
  memoryTable(out, comparison);
  notes(out, comparison);
  out << machineMarkdown(comparison.environment, comparison.load_after);
  return out.str();
}

}  // namespace stc
