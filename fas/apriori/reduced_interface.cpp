#include "stcontact/fas/apriori/reduced_interface.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <optional>
#include <string>

#include "stcontact/fas/apriori/nested_in_time.hpp"
#include "stcontact/fas/coarse_zone.hpp"
#include "stcontact/latin/indicator.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/pgd/controlled_global_stage.hpp"
#include "stcontact/pgd/separated_history.hpp"
#include "stcontact/problem/prescribed_reach.hpp"
#include "stcontact/solver/iteration_monitor.hpp"
#include "stcontact/solver/warm_start.hpp"

namespace stc::fas {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

InterfaceHistory restricted(const InterfaceHistory& h, const std::vector<int>& rows) {
  return {h.v(rows, Eigen::all), h.lambda(rows, Eigen::all)};
}

// The history on the whole interface: `part` on `rows`, λ = 0 and v = `far_v` on `far_rows`.
InterfaceHistory lifted(const InterfaceHistory& part, const std::vector<int>& rows, const std::vector<int>& far_rows,
                        const Eigen::MatrixXd& far_v, int all_rows) {
  InterfaceHistory h = InterfaceHistory::zerosWithRows(all_rows, part.numSteps());
  h.v(rows, Eigen::all) = part.v;
  h.lambda(rows, Eigen::all) = part.lambda;
  h.v(far_rows, Eigen::all) = far_v;
  return h;
}

// The nodes of `far` whose gap g0 + v_n is negative at some instant (far_v: their rows, d per node).
std::vector<int> penetrating(const ContactInterface& contact, const std::vector<int>& far, const Eigen::MatrixXd& far_v) {
  const int d = contact.dimension;
  std::vector<int> out;
  for (size_t f = 0; f < far.size(); ++f) {
    const int i = far[f];
    if ((contact.initial_gap[i] + far_v.row(d * static_cast<Eigen::Index>(f)).array()).minCoeff() < 0.0) out.push_back(i);
  }
  return out;
}

// What the solves before the current one add to its records: the first relaxation, earlier rounds,
// and the time before its own clock started.
struct Offsets {
  int iterations = 0, relaxations = 0, sparse_solves = 0;
  double wall_s = 0.0;
};

IterationRecord shifted(IterationRecord r, const Offsets& o) {
  r.iteration += o.iterations;
  r.relaxations += o.relaxations;
  r.sparse_solves += o.sparse_solves;
  r.wall_s += o.wall_s;
  return r;
}

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
  pgd::ControlledGlobalStage stage(problem, options.stage);
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

}  // namespace

ErrorOnRows::ErrorOnRows(const ErrorMeasure& whole, std::vector<int> rows, int all_rows)
    : whole_(whole), rows_(std::move(rows)), all_rows_(all_rows) {}

double ErrorOnRows::relativeError(const Eigen::MatrixXd& lambda) const {
  const auto start = Clock::now();
  Eigen::MatrixXd all = Eigen::MatrixXd::Zero(all_rows_, lambda.cols());
  all(rows_, Eigen::all) = lambda;
  const double error = whole_.relativeError(all);
  nanoseconds_ += std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start).count();
  return error;
}

namespace {

// The energy the far nodes' lift may drop (ResponseBasis::displacementOn): what the converged
// estimate leaves of the tolerance, (τ − ε_est)² E, E the last iterate's energy. With ε_est bounding
// the true error e, the lifted field is within e + (τ − ε_est) ≤ τ of the reference in the true
// error's measure (triangle inequality). Nothing (the exact lift) when the solve did not converge.
double liftBudget(const SolveSummary& summary, double tolerance) {
  if (!summary.converged() || summary.history.empty()) return 0.0;
  const IterationRecord& last = summary.history.back();
  if (!last.energy || !(last.error_estimate < tolerance)) return 0.0;
  const double slack = tolerance - last.error_estimate;
  return slack * slack * *last.energy;
}

}  // namespace

SolveResult solveAprioriOn(const Problem& problem, const FasAprioriOptions& options, const SolveInputs& inputs,
                           const Eigen::SparseMatrix<double>& B_far, Eigen::MatrixXd& far_v,
                           const SeparatedCoarseBasis& coarse_basis) {
  pgd::ControlledGlobalStage stage(problem, options.stage);
  if (inputs.basis_seed) stage.seed(*inputs.basis_seed);
  // The loads' responses and a warm start's directions, solved before the iteration.
  SolveResult result = countingSolvesBefore(stage.sparseSolves(), inputs, [&](const SolveInputs& counted) {
    return solveFasNestedInTime(problem, stage, options, counted, coarse_basis);
  });
  result.interface_directions = stage.basis().directions();
  // What follows the iteration may solve: the responses of the spatial modes, the far nodes' lift
  // (response_basis.hpp); the last record counts those solves.
  const long before = stage.sparseSolves();
  if (inputs.spatial_modes) result.spatial_modes = pgd::energyModes(stage.basis(), stage.coordinates());
  far_v = stage.basis().displacementOn(B_far, stage.coordinates(), liftBudget(result.summary, options.fas.stop.tolerance));
  result.summary.addSolvesAfterIteration(stage.sparseSolves() - before);
  return result;
}

namespace {

// Step 1 from the prescribed motion, when the loading is one: the nodes within its reach and, without
// a warm start, its rigid motion as the start. None when it gives no zone to solve on.
std::optional<SolveResult> solveWithinPrescribedReach(const Problem& problem, const FasAprioriOptions& options,
                                                      const SolveInputs& inputs, ZoneStart from,
                                                      const SeparatedCoarseBasis& coarse_basis) {
  const std::optional<Eigen::MatrixXd> W = prescribedTranslation(problem);
  if (!W) return std::nullopt;
  std::vector<int> reach = nodesWithinReach(problem.contact, *W, options.zone.reach_margin);
  if (reach.empty() || reach.size() > options.zone.whole_share * problem.contact.size()) return std::nullopt;
  InterfaceHistory rigid;
  if (!from.start) {
    rigid = rigidMotionHistory(problem.contact, *W);
    from.start = &rigid;
  }
  from.hat = from.start;
  from.zone_origin = inputs.start ? "the zone within reach of the prescribed motion"
                                  : "the zone within reach of the prescribed motion, started from it carried rigidly";
  return solveAprioriOnZone(problem, options, inputs, std::move(reach), from, coarse_basis);
}

}  // namespace

SolveResult solveAprioriOnContactZone(const Problem& problem, const FasAprioriOptions& options,
                                      const SolveInputs& inputs, const SeparatedCoarseBasis& coarse_basis) {
  const auto start = Clock::now();
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

namespace {

// Whether the round after `last` starts from where it stopped (its ŝ and directions): after every
// ending but a numerical issue, which sends it back to the first start (ZoneRounds::startNext).
bool nextRoundGoesOn(const SolveSummary& last) { return last.termination != Termination::NumericalIssue; }

// The rounds of solveAprioriOnZone: what they have spent so far, and where the next one starts.
class ZoneRounds {
 public:
  ZoneRounds(const Problem& problem, const FasAprioriOptions& options, const SolveInputs& inputs, const ZoneStart& from,
             const SeparatedCoarseBasis& coarse_basis)
      : problem_(problem), options_(options), inputs_(inputs), from_(from), coarse_basis_(coarse_basis),
        first_hat_(from.hat), measure_s_(from.measure_s) {
    if (from.first) {
      history_.push_back(*from.first);
      offsets_ = {from.first->iteration, from.first->relaxations, from.first->sparse_solves, 0.0};
    }
    if (inputs.basis_seed) seed_ = *inputs.basis_seed;
  }

  /// One restricted solve on `zone`, lifted to the whole interface; `penetrating` receives the nodes
  /// left out that its displacement pushes into the obstacle.
  SolveResult solve(const std::vector<int>& zone, std::vector<int>& penetrating_nodes) {
    const ContactInterface& contact = problem_.contact;
    const int d = contact.dimension;
    const std::vector<int> far = otherNodes(contact.size(), zone);
    const std::vector<int> rows = rowsOfNodes(d, zone), far_rows = rowsOfNodes(d, far);
    // The whole interface at the scene's k needs no copy of the problem (restrictToNodes of every
    // node is its interface). On a large 2D zone the search direction grows with it
    // (ReducedInterfaceOptions::search_growth).
    const double scale = options_.zone.searchScaleOn(static_cast<int>(zone.size()), d);
    const bool whole = far.empty(), own_problem = !whole || scale != 1.0;
    Problem part;
    if (own_problem) {
      part = problem_;
      part.contact = restrictToNodes(contact, zone);
      part.contact.search_direction *= scale;
    }
    if (inputs_.reference) measure_.emplace(*inputs_.reference, rows, contact.rows());
    const Offsets before = offsets_;
    std::optional<double> clock;  // the restricted solve's clock starts after its set-up
    const IterationCallback shift = [&](const IterationRecord& r) {
      if (!clock) clock = clockOffset(r.wall_s);
      return !inputs_.callback || inputs_.callback(shifted(r, withClock(before, *clock)));
    };
    const Eigen::MatrixXd part_seed = seed_ ? Eigen::MatrixXd((*seed_)(rows, Eigen::all)) : Eigen::MatrixXd();
    // The iteration cap holds for the rounds together, and a restricted round gets half of what is
    // left: one that needs more is failing (κ = 0.01 of the hard cases), and the other half is the
    // whole interface's, from where the round stopped.
    FasAprioriOptions budget = options_;
    const int left = options_.fas.stop.max_iterations - offsets_.relaxations;
    budget.fas.stop.max_iterations = std::max(1, whole ? left : left / 2);
    // Nested iteration in time (nested_in_time.hpp) begins a solve from scratch: not from a warm
    // start, nor in a later round, which starts from the last one.
    if (inputs_.start || rounds_++ > 0) budget.nested.instants = 0;
    Eigen::MatrixXd far_v;
    const InterfaceHistory start = startOn(rows);
    SolveInputs round;
    round.reference = measure_ ? &*measure_ : nullptr;
    round.callback = shift;
    round.start = &start;
    round.basis_seed = seed_ ? &part_seed : nullptr;
    round.spatial_modes = inputs_.spatial_modes;
    // B of the nodes left out: the rows of their sub-interface.
    SolveResult r = solveAprioriOn(own_problem ? part : problem_, budget, round, restrictToNodes(contact, far).B, far_v,
                                   coarse_basis_);
    count(r.summary, withClock(before, clock.value_or(clockOffset(r.summary.wall_s))));
    penetrating_nodes = penetrating(contact, far, far_v);
    return liftedResult(std::move(r), rows, far_rows, far_v);
  }

  /// Whether the rounds must stop: the caller stopped them or the iteration cap is spent.
  bool spent(const SolveSummary& last) const {
    return last.termination == Termination::StoppedByCallback ||
           offsets_.relaxations >= options_.fas.stop.max_iterations;
  }

  /// The next round starts from `last` (its ŝ and directions taken), also when it stopped at its share
  /// of the cap or stagnated: an admissible iterate of the zone, its far nodes open, is a start as
  /// good as the first and most often better (κ = 0.01 of the hard cases: 1116 relaxations in all
  /// against 1874 from the first start, docs/hard_cases.md). After a numerical issue, the first start.
  void startNext(SolveResult&& last) {
    if (measure_) measure_s_ += measure_->secondsSpent();
    measure_.reset();
    if (nextRoundGoesOn(last.summary)) {
      hat_ = std::move(*last.contact_admissible);
      seed_ = std::move(last.interface_directions);
      return;
    }
    hat_.reset();
    first_hat_ = from_.start;
    seed_.reset();
    if (inputs_.basis_seed) seed_ = *inputs_.basis_seed;
  }

  /// The summary of all rounds: their history, counts and time, and the stage that says what they did
  /// (`rounds`, the last zone's `nodes`). A solve converged on its estimate counts the iterations of all
  /// in its reason (one certified without contact keeps the certificate's reason); one stopped by the
  /// cap names the solve's cap, not the last round's share of it.
  void finish(SolveSummary& summary, const std::string& rounds, int nodes) {
    summary.history = std::move(history_);
    summary.iterations = offsets_.iterations;
    summary.relaxations = offsets_.relaxations;
    summary.wall_s = clockOffset(0.0);
    if (summary.converged() && !summary.history.empty() &&
        summary.history.back().error_estimate <= options_.fas.stop.tolerance)
      summary.reason = convergedReason(summary.history.back(), options_.fas.stop.tolerance);
    if (summary.termination == Termination::MaxIterations && !summary.history.empty())
      summary.reason = iterationLimitReason(options_.fas.stop.max_iterations, summary.history.back().indicator);
    SolveStage stage{SolveStage::Kind::ContactZone, "solved on " + rounds, 0, 0, 0.0, nodes, rounds_};
    if (!from_.zone_origin.empty()) stage.description += " (" + from_.zone_origin + ")";
    summary.addStage(std::move(stage));
  }

 private:
  // The rows `rows` of the next round's start: the last round's ŝ, or the first start (s = 0 when none).
  InterfaceHistory startOn(const std::vector<int>& rows) const {
    const InterfaceHistory* hat = hat_ ? &*hat_ : first_hat_;
    if (hat) return restricted(*hat, rows);
    return InterfaceHistory::zerosWithRows(static_cast<int>(rows.size()), problem_.numSteps());
  }
  // Seconds on this solve's clock (from from_.clock, the true-error measure left out as the
  // monitor leaves it out) less `wall_s`.
  double clockOffset(double wall_s) const {
    return secondsSince(from_.clock) - measure_s_ - (measure_ ? measure_->secondsSpent() : 0.0) - wall_s;
  }
  static Offsets withClock(Offsets o, double wall_s) {
    o.wall_s = wall_s;
    return o;
  }
  void count(const SolveSummary& sum, const Offsets& o) {
    for (const IterationRecord& record : sum.history) history_.push_back(shifted(record, o));
    offsets_.iterations += sum.iterations;
    offsets_.relaxations += sum.relaxations;
    if (!history_.empty()) offsets_.sparse_solves = history_.back().sparse_solves;
  }
  // The result on the whole interface: λ = 0 and v = far_v on the rows left out.
  SolveResult liftedResult(SolveResult r, const std::vector<int>& rows, const std::vector<int>& far_rows,
                     const Eigen::MatrixXd& far_v) const {
    const int all_rows = problem_.contact.rows();
    SolveResult out;
    out.interface = lifted(r.interface, rows, far_rows, far_v, all_rows);
    out.contact_admissible = lifted(r.admissible(), rows, far_rows, far_v, all_rows);
    out.interface_directions = Eigen::MatrixXd::Zero(all_rows, r.interface_directions.cols());
    out.interface_directions(rows, Eigen::all) = r.interface_directions;
    out.spatial_modes = std::move(r.spatial_modes);
    out.summary = std::move(r.summary);
    return out;
  }

  const Problem& problem_;
  const FasAprioriOptions& options_;
  const SolveInputs& inputs_;
  const ZoneStart& from_;
  const SeparatedCoarseBasis& coarse_basis_;
  const InterfaceHistory* first_hat_;     ///< where the first round starts (null: s = 0)
  std::optional<InterfaceHistory> hat_;  ///< where a later round starts, when not from first_hat_
  std::optional<Eigen::MatrixXd> seed_;
  Offsets offsets_;
  std::vector<IterationRecord> history_;
  std::optional<ErrorOnRows> measure_;
  double measure_s_ = 0.0;  ///< true-error measures of earlier rounds
  int rounds_ = 0;          ///< restricted solves so far
};

std::string zoneSize(const std::vector<int>& zone, int n) {
  return std::to_string(zone.size()) + " of " + std::to_string(n) + " contact nodes";
}

// Why a round follows `last`: the nodes left out that penetrated, or how it stopped and where the
// next one starts (ZoneRounds::startNext).
std::string whyAnotherRound(const SolveSummary& last, std::size_t penetrating) {
  if (last.converged()) return "(" + std::to_string(penetrating) + " nodes left out penetrating) ";
  const char* from = nextRoundGoesOn(last) ? "from where it stopped" : "from the start";
  return "(that solve " + std::string(toString(last.termination)) + ", " + from + ") ";
}

}  // namespace

SolveResult solveAprioriOnZone(const Problem& problem, const FasAprioriOptions& options, const SolveInputs& inputs,
                               std::vector<int> zone, const ZoneStart& from,
                               const SeparatedCoarseBasis& coarse_basis) {
  const int n = problem.contact.size();
  ZoneRounds rounds(problem, options, inputs, from, coarse_basis);
  std::string log;  // what each round did, for the summary's message
  for (int round = 1;; ++round) {
    std::vector<int> wrong;
    SolveResult out = rounds.solve(zone, wrong);
    const SolveSummary& sum = out.summary;
    if ((wrong.empty() && sum.converged()) || rounds.spent(sum) || static_cast<int>(zone.size()) == n) {
      log += zoneSize(zone, n) + (wrong.empty() ? "" : ", " + std::to_string(wrong.size()) + " nodes left out penetrating");
      rounds.finish(out.summary, log, static_cast<int>(zone.size()));
      return out;
    }
    // Nodes left out that penetrate join the zone and the solve goes on from where it stopped; after
    // options.zone.rounds rounds, or a round that did not converge, the whole interface.
    log += zoneSize(zone, n) + ", then " + whyAnotherRound(sum, wrong.size());
    const bool converged = sum.converged();
    rounds.startNext(std::move(out));
    zone.insert(zone.end(), wrong.begin(), wrong.end());
    std::sort(zone.begin(), zone.end());
    if (!converged || round >= options.zone.rounds) zone = otherNodes(n, {});
  }
}

}  // namespace stc::fas
