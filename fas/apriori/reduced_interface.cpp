#include "stcontact/fas/apriori/reduced_interface.hpp"

#include <chrono>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "stcontact/fas/apriori/zone_rounds.hpp"
#include "stcontact/fas/coarse_zone.hpp"
#include "stcontact/latin/indicator.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/pgd/controlled_global_stage.hpp"
#include "stcontact/problem/prescribed_reach.hpp"
#include "stcontact/solver/warm_start.hpp"

namespace stc::fas {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The first relaxation on the whole interface: its local stage ŝ (the restricted solves' start), the
// nodes of its contact zone, and its record (iteration 1 of the history).
struct FirstRelaxation {
  InterfaceHistory s, hat;
  std::vector<int> zone;
  IterationRecord record;
  double measure_s = 0.0;  ///< time spent measuring its true error
};

FirstRelaxation firstRelaxation(const Problem& problem, const FasAprioriOptions& options, const SolveInputs& inputs,
                                Clock::time_point start) {
  pgd::ControlledGlobalStage stage(problem, options.stage, *inputs.operators);
  stage.notePhases(inputs.phase_note);  // where a long enrichment is
  if (inputs.basis_seed) stage.seed(*inputs.basis_seed);
  FirstRelaxation first;
  stage.solve(startingHistory(problem, inputs), first.s);
  latin::localStage(problem.contact, first.s, first.hat);
  first.zone = coarseZone(problem.contact, first.s, first.hat, options.zone.margin).nodes;
  if (first.zone.empty()) first.zone = coarseZone(problem.contact, first.s, first.hat).nodes;
  IterationRecord& r = first.record;
  const auto measured = Clock::now();
  if (inputs.reference && inputs.reference->defined()) r.error = inputs.reference->relativeError(first.s.lambda);
  first.measure_s = secondsSince(measured);
  r.iteration = r.relaxations = 1;
  r.indicator = latin::indicator(problem.contact.search_direction, first.s, first.hat);
  r.error_estimate = std::numeric_limits<double>::infinity();  // no contraction rate yet
  r.rank = stage.rank();
  r.sparse_solves = static_cast<int>(stage.sparseSolves());
  r.wall_s = secondsSince(start) - first.measure_s;
  return first;
}

// The result when the caller stops the solve at the first relaxation.
SolveResult stoppedAtFirst(const FirstRelaxation& first, const std::string& solver) {
  SolveResult out;
  out.interface = first.s;
  out.contact_admissible = first.hat;
  SolveSummary& sum = out.summary;
  sum.solver = solver;
  sum.termination = Termination::StoppedByCallback;
  sum.reason = "stopped by the caller after the first relaxation";
  sum.composeMessage();
  sum.history = {first.record};
  sum.iterations = sum.relaxations = 1;
  sum.indicator = first.record.indicator;
  sum.error_estimate = first.record.error_estimate;
  sum.error = first.record.error;
  sum.wall_s = first.record.wall_s;
  return out;
}

// Step 1 from the prescribed motion, when the loading is one: the nodes within its reach and, without
// a warm start, its rigid motion as the start. None when it gives no zone to solve on.
std::optional<SolveResult> solveWithinPrescribedReach(const Problem& problem, const FasAprioriOptions& options,
                                                      const SolveInputs& inputs, ZoneStart from,
                                                      const SeparatedCoarseBasis& coarse_basis) {
  const std::optional<Eigen::MatrixXd> W = prescribedTranslation(problem);
  if (!W) return std::nullopt;
  std::vector<int> reach = nodesWithinReach(problem.contact, *W, options.zone.reach_margin);
  if (reach.empty() || reach.size() > options.zone.whole_share * problem.contact.size()) return std::nullopt;
  if (!from.start)  // its rows formed as each round reads them: no whole-interface history held
    from.start = StartOnRows([&contact = problem.contact, W = *W](const std::vector<int>& rows) {
      return rigidMotionHistory(contact, W, rows);
    });
  from.hat = from.start;
  from.zone_origin = inputs.start ? "the zone within reach of the prescribed motion"
                                  : "the zone within reach of the prescribed motion, started from it carried rigidly";
  return solveAprioriOnZone(problem, options, inputs, std::move(reach), from, coarse_basis);
}

}  // namespace

SolveResult solveAprioriOnContactZone(const Problem& problem, const FasAprioriOptions& options,
                                      const SolveInputs& given, const SeparatedCoarseBasis& coarse_basis) {
  SolveInputs inputs = given;  // the solve's clock, and one owner of its operators for every round
  inputs.origin = given.origin.clocked();
  std::unique_ptr<PreparedOperators> own;
  inputs.operators = &operatorsOr(given.operators, own);
  const auto start = *inputs.origin.clock;
  if (inputs.start) requireFits(*inputs.start, problem);
  if (inputs.basis_seed) requireFits(*inputs.basis_seed, problem);
  ZoneStart from;
  from.start = inputs.start;
  from.clock = start;
  if (std::optional<SolveResult> out = solveWithinPrescribedReach(problem, options, inputs, from, coarse_basis))
    return std::move(*out);
  const FirstRelaxation first = firstRelaxation(problem, options, inputs, start);
  if (inputs.callback && !inputs.callback(first.record)) return stoppedAtFirst(first, coarse_basis.solver);
  const int n = problem.contact.size();
  std::vector<int> zone = first.zone;
  if (zone.empty() || zone.size() > options.zone.whole_share * n) zone = otherNodes(n, {});
  from.hat = &first.hat;
  from.first = first.record;
  from.measure_s = first.measure_s;
  from.zone_origin = "first relaxation on all " + std::to_string(n);
  return solveAprioriOnZone(problem, options, inputs, std::move(zone), from, coarse_basis);
}

}  // namespace stc::fas
