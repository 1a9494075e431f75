#include "stcontact/studies/work_precision.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stc {

std::optional<WorkPoint> firstReaching(const std::vector<WorkPoint>& points, double target) {
  for (const WorkPoint& p : points)
    if (p.error && *p.error <= target) return p;
  return std::nullopt;
}

double median(std::vector<double> values) {
  if (values.empty()) throw std::invalid_argument("median of an empty set");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

bool copyErrors(const std::vector<WorkPoint>& measured, std::vector<WorkPoint>& timed, double relative_tolerance) {
  bool same = measured.size() == timed.size();
  for (std::size_t i = 0; i < timed.size(); ++i) {
    timed[i].error.reset();
    if (i >= measured.size() || measured[i].iteration != timed[i].iteration) {
      same = false;
      continue;
    }
    const double a = measured[i].indicator, b = timed[i].indicator;
    if (std::abs(a - b) > relative_tolerance * std::max(std::abs(a), std::abs(b))) {
      same = false;
      continue;
    }
    timed[i].error = measured[i].error;
  }
  return same;
}

Reach reachOf(const std::vector<TimedRun>& runs, double target) {
  Reach reach;
  reach.target = target;
  std::vector<double> wall, relaxations, solves;
  for (const TimedRun& run : runs) {
    const std::optional<WorkPoint> p = firstReaching(run.points, target);
    if (!p) continue;
    wall.push_back(p->wall_s);
    relaxations.push_back(p->relaxations);
    solves.push_back(static_cast<double>(p->sparse_solves));
  }
  reach.repeats_reached = static_cast<int>(wall.size());
  if (wall.empty()) return reach;
  reach.wall_s = median(wall);
  reach.relaxations = median(relaxations);
  reach.sparse_solves = median(solves);
  return reach;
}

int medianRepeat(const std::vector<TimedRun>& runs) {
  if (runs.empty()) throw std::invalid_argument("median repeat of no runs");
  std::vector<const TimedRun*> sorted;
  for (const TimedRun& run : runs) sorted.push_back(&run);
  std::sort(sorted.begin(), sorted.end(), [](const TimedRun* a, const TimedRun* b) { return a->total_s < b->total_s; });
  return sorted[(sorted.size() - 1) / 2]->repeat;
}

}  // namespace stc
