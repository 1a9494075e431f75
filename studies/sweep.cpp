#include "stcontact/studies/sweep.hpp"

#include <algorithm>

namespace stc {
namespace {

void add(SweepTotals& totals, const SolveCost& cost) {
  ++totals.values;
  totals.converged += cost.converged();
  totals.relaxations += cost.relaxations;
  totals.sparse_solves += cost.sparse_solves;
  totals.wall_s += cost.wall_s;
}

}  // namespace

SolveCost costOf(const SolveSummary& summary, double wall_s) {
  SolveCost cost;
  cost.termination = summary.termination;
  cost.iterations = summary.iterations;
  cost.relaxations = summary.relaxations;
  cost.sparse_solves = summary.sparseSolves();
  cost.wall_s = wall_s;
  cost.indicator = summary.indicator;
  return cost;
}

EndForces endForces(const ContactInterface& contact, const InterfaceHistory& s) {
  EndForces forces;
  if (s.lambda.cols() == 0) return forces;
  const Eigen::VectorXd last = s.lambda.col(s.lambda.cols() - 1);
  for (int i = 0; i < contact.size(); ++i) {
    forces.normal += last(contact.normalRow(i));
    forces.tangential += last(contact.normalRow(i) + 1);
  }
  return forces;
}

const char* toString(WarmStart start) { return start == WarmStart::Previous ? "previous" : "zero"; }

SweepTotals warmTotals(const Sweep& sweep) {
  SweepTotals totals;
  for (const SweepPoint& p : sweep.points) add(totals, p.warm);
  return totals;
}

std::optional<SweepTotals> coldTotals(const Sweep& sweep) {
  if (!sweep.independent()) return std::nullopt;
  SweepTotals totals;
  for (const SweepPoint& p : sweep.points)
    if (p.cold) add(totals, *p.cold);
  return totals;
}

std::optional<double> largestWarmError(const Sweep& sweep) {
  std::optional<double> largest;
  for (const SweepPoint& p : sweep.points)
    if (p.warm.error) largest = std::max(largest.value_or(*p.warm.error), *p.warm.error);
  return largest;
}

}  // namespace stc
