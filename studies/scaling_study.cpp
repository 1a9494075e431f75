#include "stcontact/studies/scaling_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stc {
namespace {

constexpr double kMb = 1024.0 * 1024.0;
constexpr double kDouble = 8.0;  // bytes

double seconds(const std::optional<double>& t) { return t ? *t : std::numeric_limits<double>::quiet_NaN(); }

}  // namespace

const char* toString(Series series) { return series == Series::Mesh ? "mesh" : "time"; }

double ScalingPoint::size(Series series) const {
  return series == Series::Mesh ? comparison.n_dofs : comparison.n_steps;
}

const StrategyMeasurement* ScalingPoint::strategy(const std::string& solver) const {
  for (const StrategyMeasurement& m : comparison.strategies)
    if (m.solver == solver) return &m;
  return nullptr;
}

double ScalingPoint::timeRatioAtTolerance(const StrategyMeasurement& m) const {
  const StrategyMeasurement* incremental = strategy("incremental");
  if (!m.at_tolerance || !incremental || !incremental->at_tolerance) return NAN;
  if (!(incremental->at_tolerance->median_s > 0.0)) return NAN;
  return m.at_tolerance->median_s / incremental->at_tolerance->median_s;
}

std::vector<const ScalingPoint*> seriesPoints(const ScalingStudy& study, Series series) {
  std::vector<const ScalingPoint*> points;
  for (const ScalingPoint& p : study.points)
    if (p.in(series)) points.push_back(&p);
  std::stable_sort(points.begin(), points.end(),
                   [series](const ScalingPoint* a, const ScalingPoint* b) { return a->size(series) < b->size(series); });
  return points;
}

Reach reachAt(const ScalingStudy& study, const ScalingPoint& point, const std::string& solver) {
  const StrategyMeasurement* m = point.strategy(solver);
  if (!m) {
    Reach none;
    none.target = study.target_error;
    return none;
  }
  return reachOf(m->runs, study.target_error);
}

std::optional<double> fittedTime(const ScalingStudy& study, const ScalingPoint& point, const std::string& solver) {
  if (study.first_reach) return reachAt(study, point, solver).wall_s;
  const StrategyMeasurement* m = point.strategy(solver);
  if (!m || !m->at_tolerance || m->at_tolerance->termination != Termination::Converged) return std::nullopt;
  return m->at_tolerance->median_s;
}

std::string reachStatus(const ScalingStudy& study, const ScalingPoint& point, const std::string& solver) {
  const StrategyMeasurement* m = point.strategy(solver);
  if (!m) return "not run";
  if (!study.first_reach) return "not measured";
  if (reachAt(study, point, solver).wall_s) return "reached";
  switch (m->termination) {
    case Termination::StoppedByCallback: return "time cap";  // the only other early stop is the target
    case Termination::MaxIterations: return "iteration limit";
    case Termination::Stagnated: return "stagnated";
    case Termination::Converged: return "converged above the target";
    case Termination::NumericalIssue: return "numerical issue";
  }
  return "not reached";
}

SeriesFit fitSeries(const ScalingStudy& study, const std::string& solver, Series series) {
  SeriesFit out;
  out.solver = solver;
  out.series = series;
  std::vector<double> sizes, times;
  for (const ScalingPoint* p : seriesPoints(study, series)) {
    ++out.sizes;
    const std::optional<double> t = fittedTime(study, *p, solver);
    if (!t || !(*t > 0.0)) continue;
    ++out.sizes_reached;
    sizes.push_back(p->size(series));
    times.push_back(*t);
  }
  const bool distinct = !sizes.empty() && *std::min_element(sizes.begin(), sizes.end()) <
                                              *std::max_element(sizes.begin(), sizes.end());
  if (sizes.size() >= 2 && distinct) out.fit = fitPowerLaw(sizes, times);
  return out;
}

Crossover crossoverAgainstIncremental(const ScalingStudy& study, const std::string& solver, Series series) {
  Crossover out;
  out.solver = solver;
  out.series = series;
  for (const ScalingPoint* p : seriesPoints(study, series)) {
    const double ratio = seconds(fittedTime(study, *p, solver)) / seconds(fittedTime(study, *p, "incremental"));
    out.time_ratio.push_back(ratio);
    if (!out.first_faster && ratio < 1.0) out.first_faster = p->size(series);
  }
  const SeriesFit a = fitSeries(study, solver, series);
  const SeriesFit b = fitSeries(study, "incremental", series);
  if (!a.fit || !b.fit) return out;
  out.fitted_crossing = crossingSize(*a.fit, *b.fit);
  out.faster_beyond = a.fit->exponent < b.fit->exponent;
  return out;
}

std::vector<MemorySlope> memorySlopes(const ScalingStudy& study, const std::string& solver) {
  std::vector<MemorySlope> slopes;
  const std::vector<const ScalingPoint*> points = seriesPoints(study, Series::Time);
  for (std::size_t i = 1; i < points.size(); ++i) {
    const StrategyMeasurement* a = points[i - 1]->strategy(solver);
    const StrategyMeasurement* b = points[i]->strategy(solver);
    const int m0 = points[i - 1]->comparison.n_steps, m1 = points[i]->comparison.n_steps;
    if (!a || !b || m1 == m0) continue;
    MemorySlope s;
    s.m_from = m0;
    s.m_to = m1;
    // Growth over the baseline, so that the reference (which also grows with m) is left out.
    s.bytes_per_instant = (b->memory.growthMb() - a->memory.growthMb()) * kMb / (m1 - m0);
    const double interface_rows = static_cast<double>(points[i]->dimension) * points[i]->comparison.n_contact_nodes;
    s.interface_arrays = s.bytes_per_instant / (kDouble * interface_rows);
    s.free_dof_fields = s.bytes_per_instant / (kDouble * points[i]->free_dofs);
    slopes.push_back(s);
  }
  return slopes;
}

MemoryEstimate estimateMemory(const ScalingPoint& point) {
  const Comparison& c = point.comparison;
  const double interface = static_cast<double>(point.dimension) * c.n_contact_nodes;
  MemoryEstimate e;
  e.factor_mb = point.factor_nonzeros * kDouble / kMb;
  e.interface_history_mb = interface * c.n_steps * kDouble / kMb;
  e.displacement_history_mb = static_cast<double>(point.free_dofs) * c.n_steps * kDouble / kMb;
  e.delassus_mb = interface * interface * kDouble / kMb;
  e.condensation_mb = 2.0 * point.free_dofs * interface * kDouble / kMb;
  e.time_matrix_mb = static_cast<double>(c.n_steps) * c.n_steps * kDouble / kMb;
  return e;
}

}  // namespace stc
