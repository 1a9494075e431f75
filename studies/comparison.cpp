#include "stcontact/studies/comparison.hpp"

namespace stc {

const std::vector<double>& targetErrors() {
  static const std::vector<double> targets = {1e-2, 1e-4, 1e-6};
  return targets;
}

StrategySummary summarize(const StrategyMeasurement& measurement) {
  StrategySummary s;
  s.solver = measurement.solver;
  s.repeats = static_cast<int>(measurement.runs.size());
  for (double target : targetErrors()) s.reaches.push_back(reachOf(measurement.runs, target));
  if (measurement.runs.empty()) return s;
  std::vector<double> totals;
  for (const TimedRun& run : measurement.runs) totals.push_back(run.total_s);
  s.median_total_s = median(totals);
  s.median_repeat = medianRepeat(measurement.runs);
  return s;
}

std::optional<double> timeRatio(const StrategySummary& a, const StrategySummary& b, std::size_t t) {
  if (t >= a.reaches.size() || t >= b.reaches.size()) return std::nullopt;
  const auto& ta = a.reaches[t].wall_s;
  const auto& tb = b.reaches[t].wall_s;
  if (!ta || !tb || *tb <= 0.0) return std::nullopt;
  return *ta / *tb;
}

const StrategySummary* findSummary(const std::vector<StrategySummary>& summaries, const std::string& solver) {
  for (const StrategySummary& s : summaries)
    if (s.solver == solver) return &s;
  return nullptr;
}

std::vector<StrategySummary> summarizeAll(const Comparison& comparison) {
  std::vector<StrategySummary> summaries;
  for (const StrategyMeasurement& m : comparison.strategies) summaries.push_back(summarize(m));
  return summaries;
}

std::optional<double> timeRatioTo(const std::vector<StrategySummary>& all, const StrategySummary& s,
                                  const std::string& other, std::size_t t) {
  const StrategySummary* o = findSummary(all, other);
  return o ? timeRatio(s, *o, t) : std::nullopt;
}

}  // namespace stc
