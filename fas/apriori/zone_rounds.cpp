#include "stcontact/fas/apriori/zone_rounds.hpp"

#include <algorithm>
#include <memory>

#include "stcontact/core/threads.hpp"
#include "stcontact/fas/apriori/single_solve.hpp"
#include "stcontact/solver/iteration_monitor.hpp"
#include "stcontact/solver/warm_start.hpp"

namespace stc::fas {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

InterfaceHistory restricted(const InterfaceHistory& h, const std::vector<int>& rows) {
  return {h.v(rows, Eigen::all), h.lambda(rows, Eigen::all)};
}

// B on the interface's rows with the zone's rows empty: what it lifts is the far nodes' displacement
// laid out on the interface's rows (zero on the zone's), which liftedResult completes in place.
Eigen::SparseMatrix<double> farNodesB(const ContactInterface& contact, const std::vector<int>& rows) {
  Eigen::VectorXd far = Eigen::VectorXd::Ones(contact.rows());
  far(rows).setZero();
  Eigen::SparseMatrix<double> B = far.asDiagonal() * contact.B;
  B.prune(0.0);
  return B;
}

// The history on the whole interface: `part` on `rows`, λ = 0 and v = `v` (the far nodes'
// displacement on every row, farNodesB) elsewhere. Each entry is written once, by columns on
// threads: at 10 001 instants zeros first, the far nodes' block apart and the blocks scattered into
// them cost 2.9 s of 36 (fretting, divisions 16), most of it the first touch of fresh memory.
InterfaceHistory lifted(const InterfaceHistory& part, const std::vector<int>& rows, Eigen::MatrixXd&& v) {
  const Eigen::Index all_rows = v.rows();
  const int m = part.numSteps();
  InterfaceHistory h{std::move(v), Eigen::MatrixXd(all_rows, m)};
  parallelRanges(m, threadCount(), [&](int begin, int end) {
    for (int j = begin; j < end; ++j) {
      h.lambda.col(j).setZero();
      for (size_t i = 0; i < rows.size(); ++i) {
        h.v(rows[i], j) = part.v(static_cast<Eigen::Index>(i), j);
        h.lambda(rows[i], j) = part.lambda(static_cast<Eigen::Index>(i), j);
      }
    }
  });
  return h;
}

// The nodes of `far` whose gap g0 + v_n is negative at some instant (v: every row, d per node).
std::vector<int> penetrating(const ContactInterface& contact, const std::vector<int>& far, const Eigen::MatrixXd& v) {
  const int d = contact.dimension;
  std::vector<int> out;
  for (const int i : far)
    if ((contact.initial_gap[i] + v.row(d * static_cast<Eigen::Index>(i)).array()).minCoeff() < 0.0) out.push_back(i);
  return out;
}

// Whether the round after `last` starts from where it stopped (its ŝ and directions): after every
// ending but a numerical issue, which sends it back to the first start (ZoneRounds::startNext).
bool nextRoundGoesOn(const SolveSummary& last) { return last.termination != Termination::NumericalIssue; }

// The result on the whole interface: λ = 0 and the far nodes' displacement `v` (on every row,
// farNodesB) on the rows left out. Its contact-admissible iterate stays on the zone (the same as the
// solution elsewhere): lifted too it cost at 10 001 instants 1.4 GB more at the peak and 5 s of 36
// (fretting, divisions 16).
SolveResult liftedResult(SolveResult r, const std::vector<int>& zone, const std::vector<int>& rows,
                         Eigen::MatrixXd&& v, int all_rows) {
  SolveResult out;
  out.interface = lifted(r.interface, rows, std::move(v));
  out.contact_admissible = std::move(r).takeAdmissible();
  out.admissible_nodes = zone;
  out.interface_directions = Eigen::MatrixXd::Zero(all_rows, r.interface_directions.cols());
  out.interface_directions(rows, Eigen::all) = r.interface_directions;
  out.spatial_modes = std::move(r.spatial_modes);
  out.displacement = std::move(r.displacement);  // the free dofs': the same body on every zone
  out.summary = std::move(r.summary);
  return out;
}

// The problem on `zone` at the search direction scaled by `scale` (a copy of the body's problem).
Problem problemOn(const Problem& problem, const std::vector<int>& zone, double scale) {
  Problem part = problem;
  part.contact = restrictToNodes(problem.contact, zone);
  part.contact.search_direction *= scale;
  return part;
}

// The rounds of solveAprioriOnZone: what they have spent so far (the origin of the next round's
// records), and where the next one starts.
class ZoneRounds {
 public:
  ZoneRounds(const Problem& problem, const FasAprioriOptions& options, const SolveInputs& inputs, const ZoneStart& from,
             const SeparatedCoarseBasis& coarse_basis)
      : problem_(problem), options_(options), inputs_(inputs), from_(from), coarse_basis_(coarse_basis),
        first_hat_(from.hat), measure_s_(from.measure_s) {
    if (from.first) {
      history_.push_back(*from.first);
      done_.iterations = from.first->iteration;
      done_.relaxations = from.first->relaxations;
      done_.sparse_solves = from.first->sparse_solves;
    }
    if (inputs.basis_seed) seed_ = *inputs.basis_seed;
  }

  /// One restricted solve on `zone`, lifted to the whole interface; `penetrating` receives the nodes
  /// left out that its displacement pushes into the obstacle.
  SolveResult solve(const std::vector<int>& zone, std::vector<int>& penetrating_nodes) {
    const ContactInterface& contact = problem_.contact;
    const int d = contact.dimension;
    const std::vector<int> far = otherNodes(contact.size(), zone);
    const std::vector<int> rows = rowsOfNodes(d, zone);
    // The whole interface at the scene's k needs no copy of the problem (restrictToNodes of every
    // node is its interface). On a large 2D zone the search direction grows with it
    // (ReducedInterfaceOptions::search_growth).
    const double scale = options_.zone.searchScaleOn(static_cast<int>(zone.size()), d);
    const bool whole = far.empty();
    const std::optional<Problem> part =
        whole && scale == 1.0 ? std::nullopt : std::optional<Problem>(problemOn(problem_, zone, scale));
    if (inputs_.reference) measure_.emplace(*inputs_.reference, rows, contact.rows());
    const Eigen::MatrixXd part_seed = seed_ ? Eigen::MatrixXd((*seed_)(rows, Eigen::all)) : Eigen::MatrixXd();
    const InterfaceHistory start = startOn(rows);
    SolveInputs round;
    round.reference = measure_ ? &*measure_ : nullptr;
    round.callback = inputs_.callback;
    round.start = &start;
    round.basis_seed = seed_ ? &part_seed : nullptr;
    round.spatial_modes = inputs_.spatial_modes;
    round.separated_displacement = inputs_.separated_displacement;
    round.operators = inputs_.operators;
    round.origin = originOfNextRound();
    round.phase_note = inputs_.phase_note;
    Eigen::MatrixXd v;  // the far nodes' displacement on every row
    // B of the nodes left out on the interface's rows (farNodesB); none on the whole interface.
    SolveResult r = solveAprioriOn(part ? *part : problem_, budgetOfNextRound(whole), round,
                                   whole ? Eigen::SparseMatrix<double>(0, contact.B.cols()) : farNodesB(contact, rows), v,
                                   coarse_basis_);
    count(r.summary);
    penetrating_nodes = penetrating(contact, far, v);
    // A zone of every node is the whole interface in order (zones are increasing): nothing to lift.
    if (whole) return r;
    return liftedResult(std::move(r), zone, rows, std::move(v), contact.rows());
  }

  /// Whether the rounds must stop: the caller stopped them or the iteration cap is spent.
  bool spent(const SolveSummary& last) const {
    return last.termination == Termination::StoppedByCallback || done_.relaxations >= options_.fas.stop.max_iterations;
  }

  /// The next round starts from `last` (its ŝ and directions taken), also when it stopped at its share
  /// of the cap or stagnated: an admissible iterate of the zone, its far nodes open, is a start as
  /// good as the first and most often better (κ = 0.01 of the hard cases: 1116 relaxations in all
  /// against 1874 from the first start, docs/hard_cases.md). After a numerical issue, the first start.
  void startNext(SolveResult&& last) {
    if (measure_) measure_s_ += measure_->secondsSpent();
    measure_.reset();
    if (nextRoundGoesOn(last.summary)) {
      seed_ = std::move(last.interface_directions);
      hat_ = std::move(last).takeAdmissible();
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
    summary.iterations = done_.iterations;
    summary.relaxations = done_.relaxations;
    summary.wall_s = elapsed();
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
    if (hat_) return restricted(*hat_, rows);
    return first_hat_.rows(rows, problem_.numSteps());
  }
  // The next round's records count from the rounds so far, on the solve's clock (from_.clock) less
  // the time spent measuring true errors, as the monitor leaves out its own.
  RecordOrigin originOfNextRound() const {
    RecordOrigin o = done_;
    o.wall_s = -measure_s_;
    o.clock = from_.clock;
    o.krylov = inputs_.origin.krylov;  // the whole solve's count
    return o;
  }
  // The iteration cap holds for the rounds together, and a restricted round gets half of what is
  // left: one that needs more is failing (κ = 0.01 of the hard cases), and the other half is the
  // whole interface's, from where the round stopped. Nested iteration in time (nested_in_time.hpp)
  // begins a solve from scratch: not from a warm start, nor in a later round, which starts from the
  // last one.
  FasAprioriOptions budgetOfNextRound(bool whole) {
    FasAprioriOptions budget = options_;
    const int left = options_.fas.stop.max_iterations - done_.relaxations;
    budget.fas.stop.max_iterations = std::max(1, whole ? left : left / 2);
    if (inputs_.start || rounds_++ > 0) budget.nested.instants = 0;
    return budget;
  }
  // Seconds since from_.clock, the true-error measures left out.
  double elapsed() const {
    return secondsSince(from_.clock) - measure_s_ - (measure_ ? measure_->secondsSpent() : 0.0);
  }
  void count(const SolveSummary& sum) {
    history_.insert(history_.end(), sum.history.begin(), sum.history.end());
    done_.iterations += sum.iterations;
    done_.relaxations += sum.relaxations;
    if (!history_.empty()) done_.sparse_solves = history_.back().sparse_solves;
  }

  const Problem& problem_;
  const FasAprioriOptions& options_;
  const SolveInputs& inputs_;
  const ZoneStart& from_;
  const SeparatedCoarseBasis& coarse_basis_;
  StartOnRows first_hat_;                ///< where the first round starts (none: s = 0)
  std::optional<InterfaceHistory> hat_;  ///< where a later round starts, when not from first_hat_
  std::optional<Eigen::MatrixXd> seed_;
  RecordOrigin done_;  ///< iterations, relaxations and sparse solves of the rounds so far
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

InterfaceHistory StartOnRows::rows(const std::vector<int>& rows, int steps) const {
  if (held_) return restricted(*held_, rows);
  if (form_) return form_(rows);
  return InterfaceHistory::zerosWithRows(static_cast<int>(rows.size()), steps);
}

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

SolveResult solveAprioriOnZone(const Problem& problem, const FasAprioriOptions& options, const SolveInputs& inputs,
                               std::vector<int> zone, const ZoneStart& from,
                               const SeparatedCoarseBasis& coarse_basis) {
  const int n = problem.contact.size();
  std::unique_ptr<PreparedOperators> own;  // the rounds' operators, each prepared once
  SolveInputs shared = inputs;
  shared.operators = &operatorsOr(inputs.operators, own);
  ZoneRounds rounds(problem, options, shared, from, coarse_basis);
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
