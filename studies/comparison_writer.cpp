#include "stcontact/studies/comparison_writer.hpp"

#include <cmath>
#include <optional>
#include <sstream>

#include "stcontact/io/atomic_file.hpp"
#include "stcontact/studies/number_format.hpp"

namespace stc {
namespace {

std::optional<double> finiteOrNone(double value) {
  return std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
}

void summaryCsvHeader(std::ostream& out) {
  out << "solver,repeats,termination,iterations,relaxations,final_indicator,final_error,median_total_s";
  for (double t : targetErrors()) {
    const std::string l = targetLabel(t);
    out << ",time_to_" << l << "_s,relaxations_to_" << l << ",sparse_solves_to_" << l << ",repeats_reaching_" << l;
  }
  for (const char* other : {"latin", "incremental"})
    for (double t : targetErrors()) out << ",time_ratio_to_" << other << "_" << targetLabel(t);
  out << ",peak_rss_mb,rss_growth_mb,memory_since_reset,error_run_s,prerequisite_s,sparse_solves,final_error_estimate\n";
}

}  // namespace

std::string workPrecisionCsv(const Comparison& c) {
  std::ostringstream out;
  out.precision(10);
  out << "solver,repeat,iteration,relaxations,sparse_solves,indicator,error,wall_s\n";
  for (const auto& m : c.strategies)
    for (const TimedRun& run : m.runs)
      for (const WorkPoint& p : run.points) {
        out << m.solver << ',' << run.repeat << ',' << p.iteration << ',' << p.relaxations << ',' << p.sparse_solves
            << ',' << p.indicator << ',';
        if (p.error) out << *p.error;
        out << ',' << p.wall_s << '\n';
      }
  return out.str();
}

std::string summaryCsv(const Comparison& c) {
  const std::vector<StrategySummary> all = summarizeAll(c);
  std::ostringstream out;
  summaryCsvHeader(out);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const StrategyMeasurement& m = c.strategies[i];
    const StrategySummary& s = all[i];
    out << m.solver << ',' << s.repeats << ',' << toString(m.termination) << ',' << m.iterations << ','
        << m.relaxations << ',' << shortNumber(m.indicator) << ',' << shortNumber(m.final_error) << ','
        << shortNumber(s.median_total_s);
    for (const Reach& r : s.reaches)
      out << ',' << shortNumber(r.wall_s) << ',' << shortNumber(r.relaxations, 8) << ',' << shortNumber(r.sparse_solves, 10) << ','
          << r.repeats_reached;
    for (const char* other : {"latin", "incremental"})
      for (std::size_t t = 0; t < targetErrors().size(); ++t) out << ',' << shortNumber(timeRatioTo(all, s, other, t), 3);
    out << ',' << shortNumber(m.memory.peak_mb) << ',' << shortNumber(m.memory.growthMb()) << ','
        << (m.memory.since_reset ? "true" : "false") << ',' << shortNumber(m.error_run_s) << ','
        << shortNumber(m.prerequisite_s) << ',' << m.sparse_solves << ',' << shortNumber(finiteOrNone(m.final_error_estimate))
        << '\n';
  }
  return out.str();
}

void writeComparison(const std::filesystem::path& dir, const Comparison& comparison) {
  writeFileAtomically(dir / "work_precision.csv", workPrecisionCsv(comparison));
  writeFileAtomically(dir / "summary.csv", summaryCsv(comparison));
  writeFileAtomically(dir / "summary.md", summaryMarkdown(comparison));
}

}  // namespace stc
