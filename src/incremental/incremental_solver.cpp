#include "stcontact/incremental/incremental_solver.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "stcontact/contact/contact_state.hpp"
#include "stcontact/core/clock.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/core/interruption.hpp"
#include "stcontact/incremental/condensed_interface.hpp"
#include "stcontact/incremental/cone_newton.hpp"
#include "stcontact/incremental/form_choice.hpp"
#include "stcontact/incremental/form_switch.hpp"
#include "stcontact/incremental/lazy_delassus.hpp"
#include "stcontact/incremental/newton_instant.hpp"
#include "stcontact/incremental/reach_zone.hpp"
#include "stcontact/incremental/whole_body_newton.hpp"
#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/solver/noted_phase.hpp"

namespace stc {
namespace {

// What F depends on at instant k besides λ (see the header).
struct Instant {
  const Eigen::MatrixXd& W;
  Eigen::VectorXd v0;            // v_0(:, k)
  const Eigen::VectorXd& g0;     // g0_i
  Eigen::VectorXd vt_prev;       // v_t(t_{k−1}), zero for k = 0
  const Eigen::VectorXd& rho;    // ρ (2n_C)
  double rho_max = 0.0;
  double mu = 0.0;
  int nc() const { return static_cast<int>(g0.size()); }
};

// F at λ and the linear piece it selects: Open (λ = 0), Stick (g = 0, s = 0) or Slip (g = 0,
// λ_t = σ μ λ_n).
struct Evaluation {
  Eigen::VectorXd v;
  Eigen::VectorXd F;
  std::vector<ContactState> piece;
  std::vector<double> sigma;
};

// v = v_0 + W λ, using only the columns of nodes that carry a force.
Eigen::VectorXd interfaceDisplacement(const Instant& d, const Eigen::VectorXd& lambda) {
  Eigen::VectorXd v = d.v0;
  for (int j = 0; j < 2 * d.nc(); ++j)
    if (lambda[j] != 0.0) v.noalias() += d.W.col(j) * lambda[j];
  return v;
}

// Alart–Curnier residual, node by node (the equations in the header).
Evaluation evaluatePlane(const Instant& d, const Eigen::VectorXd& lambda) {
  Evaluation e{interfaceDisplacement(d, lambda), Eigen::VectorXd(lambda.size()),
               std::vector<ContactState>(d.nc()), std::vector<double>(d.nc(), 1.0)};
  for (int i = 0; i < d.nc(); ++i) {
    const double ln = lambda[2 * i], lt = lambda[2 * i + 1];
    const double rn = d.rho[2 * i], rt = d.rho[2 * i + 1];
    const double g = d.g0[i] + e.v[2 * i];
    const double s = e.v[2 * i + 1] - d.vt_prev[i];
    const double hat_n = ln - rn * g;  // λ̂_n before the max
    if (hat_n <= 0.0) {
      e.piece[i] = ContactState::Open;
      e.F.segment<2>(2 * i) << ln, lt;
      continue;
    }
    const double radius = d.mu * hat_n, trial = lt - rt * s;
    e.F[2 * i] = rn * g;
    if (std::abs(trial) < radius) {
      e.piece[i] = ContactState::Stick;
      e.F[2 * i + 1] = rt * s;
    } else {
      e.piece[i] = ContactState::Slip;
      e.sigma[i] = trial < 0.0 ? -1.0 : 1.0;
      e.F[2 * i + 1] = lt - e.sigma[i] * radius;
    }
  }
  return e;
}

// Newton correction Δλ for the piece selected in `e`: open nodes Δλ = −λ; slipping nodes
// Δλ_t = σ μ Δλ_n + (σ μ λ_n − λ_t); the rest from the dense system on the closed nodes
//   W(r, :) Δλ = −g_r (closed normal rows),  W(r, :) Δλ = −s_r (sticking tangential rows).
// Returns false if the system is singular or produces non-finite numbers.
bool planeNewtonStep(const Instant& d, const Eigen::VectorXd& lambda, const Evaluation& e, Eigen::VectorXd& step) {
  std::vector<int> rows;
  for (int i = 0; i < d.nc(); ++i) {
    if (e.piece[i] == ContactState::Open) continue;
    rows.push_back(2 * i);
    if (e.piece[i] == ContactState::Stick) rows.push_back(2 * i + 1);
  }
  const int na = static_cast<int>(rows.size());
  Eigen::VectorXd rhs(na);
  for (int p = 0; p < na; ++p) {
    const int r = rows[p], i = r / 2;
    rhs[p] = r % 2 == 0 ? -(d.g0[i] + e.v[r]) : -(e.v[r] - d.vt_prev[i]);
  }
  Eigen::MatrixXd M = d.W(rows, rows);
  Eigen::VectorXd c = Eigen::VectorXd::Zero(d.nc());
  std::vector<int> position(2 * d.nc(), -1);
  for (int p = 0; p < na; ++p) position[rows[p]] = p;
  for (int i = 0; i < d.nc(); ++i) {
    if (e.piece[i] == ContactState::Slip) {
      const double sm = e.sigma[i] * d.mu;
      c[i] = sm * lambda[2 * i] - lambda[2 * i + 1];
      M.col(position[2 * i]) += sm * d.W(rows, 2 * i + 1);
      rhs -= c[i] * d.W(rows, 2 * i + 1);
    } else if (e.piece[i] == ContactState::Open) {
      for (int j = 2 * i; j < 2 * i + 2; ++j)
        if (lambda[j] != 0.0) rhs += lambda[j] * d.W(rows, j);
    }
  }
  const Eigen::VectorXd x = na > 0 ? Eigen::VectorXd(M.partialPivLu().solve(rhs)) : Eigen::VectorXd();
  step = -lambda;
  for (int p = 0; p < na; ++p) step[rows[p]] = x[p];
  for (int i = 0; i < d.nc(); ++i)
    if (e.piece[i] == ContactState::Slip) step[2 * i + 1] = e.sigma[i] * d.mu * step[2 * i] + c[i];
  return step.allFinite();
}

// The plane law at one instant, as the model of solveInstantByNewton (newton_instant.hpp).
struct PlaneLaw {
  const Instant& d;
  Evaluation evaluate(const Eigen::VectorXd& lambda) const { return evaluatePlane(d, lambda); }
  bool newtonStep(const Eigen::VectorXd& lambda, const Evaluation& e, Eigen::VectorXd& step) const {
    return planeNewtonStep(d, lambda, e, step);
  }
  // S_k = max(‖λ‖∞, max_i ρ_i ‖v_0(:, k)‖∞) (header).
  double forceScale(const Eigen::VectorXd& lambda) const {
    return stc::forceScale(lambda, d.rho_max, d.v0);
  }
};

std::string describeFailure(const Problem& problem, int k, const InstantOutcome& o, int newton_total) {
  std::ostringstream msg;
  msg << "Newton failed at instant k = " << k << " (t = " << problem.times[k] << "): " << o.failure << " after "
      << o.iterations << " iterations, residual " << o.residual << "; " << newton_total
      << " Newton iterations in total";
  return msg.str();
}

// Totals over the instants, for the summary message.
struct NewtonTotals {
  int iterations = 0, most = 0, halvings = 0, fallbacks = 0;
  void add(const InstantOutcome& o) {
    iterations += o.iterations;
    most = std::max(most, o.iterations);
    halvings += o.halvings;
    fallbacks += o.fallbacks;
  }
};

std::string describeSuccess(const SolveSummary& summary, int m, const NewtonTotals& t) {
  std::ostringstream msg;
  if (summary.termination == Termination::StoppedByCallback)
    msg << "stopped by the callback after instant k = " << summary.iterations - 1 << "; ";
  msg << summary.iterations << " of " << m << " instants solved, " << t.iterations
      << " Newton iterations (at most " << t.most << " at one instant, " << t.halvings << " line-search halvings, "
      << t.fallbacks << " full-step fallbacks), largest final residual " << summary.indicator;
  return msg.str();
}

}  // namespace

namespace {

using Clock = std::chrono::steady_clock;

// When the march began, and the Krylov iterations of the solve so far (RecordOrigin::krylov).
struct MarchClock {
  Clock::time_point at;
  std::function<long long()> krylov;
};

// Marches over the instants: `solve_at(k, λ_{k−1}, v_{k−1})` solves instant k (zero fields before
// k = 0); `sparse_solves()` counts the solves so far. Fills the history, summary and message.
template <class SolveAt, class SparseSolves>
SolveResult march(const Problem& problem, const IterationCallback& callback, const MarchClock& start,
                  SolveAt&& solve_at, SparseSolves&& sparse_solves) {
  const auto elapsed = [&] { return secondsSince(start.at); };
  const int m = problem.numSteps();
  SolveResult result;
  result.interface = InterfaceHistory::zeros(problem.contact, m);
  SolveSummary& summary = result.summary;
  summary.solver = "incremental";
  summary.termination = Termination::Converged;
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(problem.contact.rows());  // λ_{k−1}, the starting point at k
  Eigen::VectorXd v = Eigen::VectorXd::Zero(problem.contact.rows());       // v_{k−1}
  NewtonTotals totals;
  for (int k = 0; k < m; ++k) {
    const InstantOutcome o = solve_at(k, lambda, v);
    totals.add(o);
    if (!o.converged) {
      summary.termination = Termination::NumericalIssue;
      summary.reason = describeFailure(problem, k, o, totals.iterations);
      break;
    }
    lambda = o.lambda;
    v = o.v;
    result.interface.lambda.col(k) = o.lambda;
    result.interface.v.col(k) = o.v;
    summary.history.push_back({k + 1, 0, o.residual, 0.0, std::nullopt, 0, sparse_solves(), elapsed(), std::nullopt,
                               start.krylov ? start.krylov() : 0});
    summary.indicator = std::max(summary.indicator, o.residual);
    if (callback && !callback(summary.history.back())) {
      summary.termination = Termination::StoppedByCallback;
      break;
    }
  }
  summary.iterations = static_cast<int>(summary.history.size());
  summary.wall_s = elapsed();
  if (summary.termination != Termination::NumericalIssue) summary.reason = describeSuccess(summary, m, totals);
  summary.composeMessage();
  return result;
}

// The plane law with the dense Delassus operator of `condensed` (the header's method).
SolveResult solvePlaneOn(const Problem& problem, CondensedInterface& condensed, const IncrementalOptions& options,
                         const IterationCallback& callback, const MarchClock& start) {
  giveHeldRowsCompliance(problem.contact, condensed.delassus);
  const int nc = problem.contact.size();
  const Eigen::VectorXd rho = condensed.delassus.diagonal().cwiseInverse();  // ρ = 1 / diag(W)
  Instant d{condensed.delassus, Eigen::VectorXd(), problem.contact.initial_gap, Eigen::VectorXd::Zero(nc), rho,
            rho.maxCoeff(), problem.contact.friction};
  const auto solve_at = [&](int k, const Eigen::VectorXd& lambda, const Eigen::VectorXd& v_previous) {
    d.v0 = condensed.free_response.col(k);
    for (int i = 0; i < nc; ++i) d.vt_prev[i] = v_previous[2 * i + 1];
    PlaneLaw law{d};
    return solveInstantByNewton(law, lambda, options.tolerance, options.max_newton_iterations);
  };
  return march(problem, callback, start, solve_at, [&] { return condensed.sparse_solves; });
}

SolveResult solvePlaneOnEveryNode(const Problem& problem, const IncrementalOptions& options,
                                  const IterationCallback& callback, const MarchClock& start, const SpdSolver& factor) {
  CondensedInterface condensed = CondensedInterface::build(problem, factor);
  return solvePlaneOn(problem, condensed, options, callback, start);
}

// A node left out of the zone penetrates when its gap is below −1e-12 times the displacement scale:
// far above the round-off of v = v_0 + W λ, far below any gap the law resolves.
constexpr double kFarPenetration = 1e-12;

std::string nodesText(std::size_t count, int n) {
  return std::to_string(count) + " of " + std::to_string(n) + " contact nodes";
}

// `on_zone`, the solve of the zone's problem, lifted to every node (the lift's solves and time
// counted in its last record) when no node left out penetrates; else `on_every_node()`, its record
// counting the zone's solves too.
template <class OnEveryNode>
SolveResult liftedOrWhole(const Problem& problem, const SpdSolver& factor, const ZoneCondensation& c,
                          SolveResult on_zone, const MarchClock& start, OnEveryNode&& on_every_node) {
  SolveSummary& summary = on_zone.summary;
  long lift_solves = 0;
  on_zone.interface = c.lift(problem.contact, factor, on_zone.interface, summary.iterations, lift_solves);
  summary.wall_s = secondsSince(start.at);
  summary.addSolvesAfterIteration(lift_solves);
  if (!summary.history.empty()) summary.history.back().wall_s = summary.wall_s;
  const int n = problem.contact.size();
  const std::string zone_text = nodesText(c.zone.size(), n);
  const std::vector<int> wrong = penetratingNodes(problem.contact, on_zone.interface, c.far, kFarPenetration);
  if (wrong.empty()) {
    summary.addStage({SolveStage::Kind::ContactZone,
                      "solved on " + zone_text + " (the zone within reach of the prescribed motion)", 0, 0, 0.0,
                      static_cast<int>(c.zone.size()), 1});
    return on_zone;
  }
  const int spent = summary.sparseSolves();
  SolveResult whole = on_every_node();
  for (IterationRecord& record : whole.summary.history) record.sparse_solves += spent;
  whole.summary.addStage({SolveStage::Kind::ContactZone,
                          "solved on every node: " + std::to_string(wrong.size()) +
                              " nodes outside the zone within reach of the prescribed motion (" + zone_text +
                              ") penetrated",
                          0, 0, 0.0, n, 2});
  return whole;
}

// The plane law on the nodes within reach of the prescribed motion (reach_zone.hpp), lifted to every
// node; on every node when there is no such zone, or when a node left out penetrates.
SolveResult solvePlane(const Problem& problem, const IncrementalOptions& options, const IterationCallback& callback,
                       const MarchClock& start, const SpdSolver& factor, const std::optional<std::vector<int>>& zone) {
  if (!zone) return solvePlaneOnEveryNode(problem, options, callback, start, factor);
  ZoneCondensation c = ZoneCondensation::build(problem, factor, *zone);
  Problem part = problem;
  part.contact = restrictToNodes(problem.contact, c.zone);
  SolveResult on_zone = solvePlaneOn(part, c.on_zone, options, callback, start);
  return liftedOrWhole(problem, factor, c, std::move(on_zone), start,
                       [&] { return solvePlaneOnEveryNode(problem, options, callback, start, factor); });
}

// The cone law on `problem`'s nodes with `delassus`, from the free response v0; the columns and
// scaling of `prepared`'s nodes are learnt before the march (ConeLaw::prepare).
SolveResult solveConeWith(const Problem& problem, const IncrementalOptions& options, const IterationCallback& callback,
                          const MarchClock& start, const Eigen::MatrixXd& v0, LazyDelassus& delassus,
                          int load_solves, const std::vector<int>& prepared) {
  ConeLaw law(problem, delassus);
  law.prepare(prepared);
  const auto solve_at = [&](int k, const Eigen::VectorXd& lambda, const Eigen::VectorXd& v_previous) {
    return law.solveInstant(v0.col(k), lambda, v_previous, options);
  };
  SolveResult result =
      march(problem, callback, start, solve_at, [&] { return load_solves + delassus.sparseSolves(); });
  result.summary.remarks.push_back(law.systemsRemark());
  result.summary.composeMessage();
  return result;
}

// The Delassus columns of `zone`'s nodes before the march (ConeLaw::prepare then finds them; or
// during it, `when` saying so, where "auto"'s whole-body march weighs or takes the interface form), told
// through `note` with a line a minute while they are solved: d solves per node, at 10⁶ dofs on
// CG + GAMG the longest part of the march with no record (more than 25 minutes on two ranks for the
// shallow press, docs/linear_solvers.md).
void learnZoneColumns(LazyDelassus& delassus, const std::vector<int>& zone, int d, const PhaseNote& note,
                      const char* when = "before the march: ") {
  if (zone.empty()) return;
  NotedPhase phase(note, when);
  const int before = delassus.sparseSolves();
  phase.begin("the Delassus columns of the " + std::to_string(zone.size()) + " nodes within reach, " +
              std::to_string(d * static_cast<int>(zone.size())) + " sparse solves");
  delassus.ensure(zone, [&](int done, int missing) {
    stopPoint();  // a caller's stop between chunks (src/core/interruption.hpp): no record before the march
    if (done < missing)  // the last chunk's line is the end's
      phase.during(std::to_string(done) + " of " + std::to_string(missing) + " nodes, " +
                   std::to_string(delassus.sparseSolves() - before) + " sparse solves");
  });
  phase.end(delassus.sparseSolves() - before);
}

// The cone law of cone_newton.hpp on every node, with the Delassus columns computed on demand; those
// of `zone`'s nodes first, in blocks on every thread (most of those the march would ask for a few at
// a time).
SolveResult solveConeOnEveryNode(const Problem& problem, const IncrementalOptions& options,
                                 const IterationCallback& callback, const MarchClock& start, const SpdSolver& factor,
                                 const std::optional<std::vector<int>>& zone, const PhaseNote& phase_note) {
  const Eigen::MatrixXd v0 = freeInterfaceResponse(problem, factor);
  LazyDelassus delassus(problem, factor);
  if (zone) learnZoneColumns(delassus, *zone, problem.contact.dimension, phase_note);
  SolveResult result = solveConeWith(problem, options, callback, start, v0, delassus,
                                     static_cast<int>(problem.loads.size()), zone.value_or(std::vector<int>()));
  result.summary.remarks.push_back(delassus.remark(problem.contact.size()));
  result.summary.composeMessage();
  return result;
}

// The cone law on the zone, with its Delassus operator from the factor's trailing block (no solve),
// lifted to every node; on every node, lazily, when the factor does not condense the zone or a node
// left out penetrates.
SolveResult solveCone(const Problem& problem, const IncrementalOptions& options, const IterationCallback& callback,
                      const MarchClock& start, const SpdSolver& factor, const std::optional<std::vector<int>>& zone,
                      const PhaseNote& phase_note) {
  const auto on_every_node = [&] {
    return solveConeOnEveryNode(problem, options, callback, start, factor, zone, phase_note);
  };
  if (!zone || !factor.condenses(restrictToNodes(problem.contact, *zone).B)) return on_every_node();
  ZoneCondensation c = ZoneCondensation::build(problem, factor, *zone);
  Problem part = problem;
  part.contact = restrictToNodes(problem.contact, c.zone);
  LazyDelassus delassus(part, std::move(c.on_zone.delassus));
  std::vector<int> every(c.zone.size());  // the part's nodes 0 … |Z| − 1
  std::iota(every.begin(), every.end(), 0);
  SolveResult on_zone = solveConeWith(part, options, callback, start, c.on_zone.free_response, delassus,
                                      c.on_zone.sparse_solves, every);
  std::ostringstream note;
  note << "Delassus operator of the " << c.zone.size() << " zone nodes from the factorisation ("
       << delassus.bytes() / 1e6 << " MB)";
  on_zone.summary.remarks.push_back(note.str());
  on_zone.summary.composeMessage();
  return liftedOrWhole(problem, factor, c, std::move(on_zone), start, on_every_node);
}

// "auto"'s whole-body march, turning to the interface form when its measured cost says so
// (form_switch.hpp): the columns solved with learnZoneColumns's progress notes.
SolveResult solveWholeBodyOrSwitch(const Problem& problem, const IncrementalOptions& options,
                                   const IterationCallback& callback, const MarchClock& start,
                                   const SpdSolver& stiffness, const std::vector<int>& zone, const PhaseNote& note) {
  const int d = problem.contact.dimension;
  FormSwitch form(problem, stiffness, zone,
                  [&](LazyDelassus& delassus, const std::vector<int>& nodes) {
                    learnZoneColumns(delassus, nodes, d, note, "during the march, for the interface form: ");
                  });
  const auto solve_at = [&](int k, const Eigen::VectorXd& lambda, const Eigen::VectorXd& v_previous) {
    return form.solve(k, lambda, v_previous, options);
  };
  SolveResult result = march(problem, callback, start, solve_at, [&] { return form.solves(); });
  for (std::string& remark : form.remarks()) result.summary.remarks.push_back(std::move(remark));
  result.summary.composeMessage();
  result.summary.incremental_form = nameOf(form.finalForm());
  return result;
}

// The whole-body form (whole_body_newton.hpp) on `stiffness`.
SolveResult solveWholeBody(const Problem& problem, const IncrementalOptions& options,
                           const IterationCallback& callback, const MarchClock& start, const SpdSolver& stiffness) {
  WholeBodyLaw law(problem, stiffness);
  const auto solve_at = [&](int k, const Eigen::VectorXd& lambda, const Eigen::VectorXd& v_previous) {
    return law.solve(k, lambda, v_previous, options.tolerance, options.max_newton_iterations);
  };
  SolveResult result = march(problem, callback, start, solve_at, [&] { return law.solves(); });
  std::ostringstream note;
  note << "whole-body form: " << law.solves() << " sparse solves with dofs held";
  result.summary.remarks.push_back(note.str());
  result.summary.composeMessage();
  return result;
}

// `result` with `remark` among its remarks (none when empty).
SolveResult remarked(SolveResult result, const std::string& remark) {
  if (remark.empty()) return result;
  result.summary.remarks.push_back(remark);
  result.summary.composeMessage();
  return result;
}

}  // namespace

SolveResult solveIncremental(const Problem& problem, const IncrementalOptions& options, const SolveInputs& inputs) {
  const IterationCallback& callback = inputs.callback;
  options.validate();
  const MarchClock start{Clock::now(), inputs.origin.krylov};
  std::unique_ptr<PreparedOperators> own;
  PreparedOperators& operators = operatorsOr(inputs.operators, own);
  // The zone's dofs ordered last: its Delassus operator from the factorisation (reach_zone.hpp).
  const std::optional<std::vector<int>> zone = options.zone_within_reach ? reachZone(problem) : std::nullopt;
  const std::vector<int> zone_dofs = zone ? dofsReadBy(restrictToNodes(problem.contact, *zone).B) : std::vector<int>();
  const std::shared_ptr<const SpdSolver> factor =
      operators.stiffnessFree(problem, {zone_dofs, CholmodFactor::kTrailingWork});
  const FormChoice choice = chooseIncrementalForm(options.form, problem, *factor, zone);
  const auto solve = [&] {
    if (choice.form == IncrementalForm::WholeBody && options.form == IncrementalForm::Auto)
      return solveWholeBodyOrSwitch(problem, options, callback, start, *factor, *zone, inputs.phase_note);
    if (choice.form == IncrementalForm::WholeBody) return solveWholeBody(problem, options, callback, start, *factor);
    if (problem.contact.dimension == 3 || options.cone_law)
      return solveCone(problem, options, callback, start, *factor, zone, inputs.phase_note);
    return solvePlane(problem, options, callback, start, *factor, zone);
  };
  SolveResult result = remarked(solve(), choice.reason);
  if (result.summary.incremental_form.empty()) result.summary.incremental_form = nameOf(choice.form);
  return result;
}

}  // namespace stc
