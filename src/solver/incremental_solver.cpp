#include "src/solver/incremental_solver.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "src/contact/contact_state.hpp"
#include "src/core/input_error.hpp"
#include "src/linalg/spd_factor.hpp"
#include "src/solver/condensed_interface.hpp"

namespace stc {
namespace {

constexpr double kArmijo = 1e-4;   // sufficient decrease of ‖F‖₂ along the step
constexpr int kMaxHalvings = 12;   // smallest step length tried: 2⁻¹²

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
Evaluation evaluate(const Instant& d, const Eigen::VectorXd& lambda) {
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
bool newtonStep(const Instant& d, const Eigen::VectorXd& lambda, const Evaluation& e, Eigen::VectorXd& step) {
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

struct InstantOutcome {
  Eigen::VectorXd lambda;
  Eigen::VectorXd v;
  double residual = 0.0;  // final ‖F‖∞ / S_k
  int iterations = 0, halvings = 0, fallbacks = 0;
  bool converged = false;
  std::string failure;
};

// S_k = max(‖λ‖∞, max_i ρ_i ‖v_0(:, k)‖∞) (header).
double forceScale(const Instant& d, const Eigen::VectorXd& lambda) {
  return std::max(lambda.lpNorm<Eigen::Infinity>(), d.rho_max * d.v0.lpNorm<Eigen::Infinity>());
}

// Backtracking on ‖F‖₂ from λ along `step`; full step when no length decreases it.
void lineSearch(const Instant& d, const Eigen::VectorXd& step, InstantOutcome& out, Evaluation& e) {
  const double phi0 = e.F.norm();
  Evaluation full = evaluate(d, out.lambda + step);
  double alpha = 1.0;
  Evaluation trial = full;
  for (int h = 0; h <= kMaxHalvings; ++h) {
    if (h > 0) trial = evaluate(d, out.lambda + alpha * step);
    if (trial.F.norm() <= (1.0 - kArmijo * alpha) * phi0) {
      out.lambda += alpha * step;
      e = std::move(trial);
      out.halvings += h;
      return;
    }
    alpha *= 0.5;
  }
  out.lambda += step;
  e = std::move(full);
  ++out.fallbacks;
}

// Semismooth Newton at one instant from λ_{k−1}.
InstantOutcome solveInstant(const Instant& d, const Eigen::VectorXd& start, const IncrementalOptions& options) {
  InstantOutcome out;
  out.lambda = start;
  Evaluation e = evaluate(d, out.lambda);
  for (;; ++out.iterations) {
    const double scale = forceScale(d, out.lambda), r = e.F.lpNorm<Eigen::Infinity>();
    out.residual = scale > 0.0 ? r / scale : (r > 0.0 ? INFINITY : 0.0);
    if (!e.F.allFinite() || !std::isfinite(out.residual)) {  // lpNorm's max can skip a NaN
      out.failure = "non-finite residual";
      break;
    }
    if (r <= options.tolerance * scale) {
      out.converged = true;
      break;
    }
    if (out.iterations == options.max_newton_iterations) {
      out.failure = "no convergence";
      break;
    }
    Eigen::VectorXd step;
    if (!newtonStep(d, out.lambda, e, step)) {
      out.failure = "singular or non-finite Newton system";
      break;
    }
    lineSearch(d, step, out, e);
  }
  out.v = std::move(e.v);
  return out;
}

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

void IncrementalOptions::validate() const {
  std::ostringstream msg;
  if (!(tolerance > 0.0 && tolerance < 1.0))
    msg << "IncrementalOptions.tolerance = " << tolerance << " must be finite and in (0, 1)";
  else if (max_newton_iterations < 1)
    msg << "IncrementalOptions.max_newton_iterations = " << max_newton_iterations << " must be >= 1";
  if (!msg.str().empty()) throw InputError(msg.str());
}

SolveResult solveIncremental(const Problem& problem, const IncrementalOptions& options,
                             const IterationCallback& callback) {
  options.validate();
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const SpdFactor factor(problem.stiffness_free, "the free-dof stiffness K_ff");
  const CondensedInterface condensed = CondensedInterface::build(problem, factor);
  const int nc = problem.contact.size(), m = problem.numSteps();
  const Eigen::VectorXd rho = condensed.delassus.diagonal().cwiseInverse();  // ρ = 1 / diag(W)

  SolveResult result;
  result.interface = InterfaceHistory::zeros(nc, m);
  SolveSummary& summary = result.summary;
  summary.solver = "incremental";
  summary.termination = Termination::Converged;
  Instant d{condensed.delassus, Eigen::VectorXd(), problem.contact.initial_gap, Eigen::VectorXd::Zero(nc), rho,
            rho.maxCoeff(), problem.contact.friction};
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(2 * nc);  // λ_{k−1}, the starting point at k
  NewtonTotals totals;
  for (int k = 0; k < m; ++k) {
    d.v0 = condensed.free_response.col(k);
    const InstantOutcome o = solveInstant(d, lambda, options);
    totals.add(o);
    if (!o.converged) {
      summary.termination = Termination::NumericalIssue;
      summary.message = describeFailure(problem, k, o, totals.iterations);
      break;
    }
    lambda = o.lambda;
    result.interface.lambda.col(k) = o.lambda;
    result.interface.v.col(k) = o.v;
    for (int i = 0; i < nc; ++i) d.vt_prev[i] = o.v[2 * i + 1];
    summary.history.push_back({k + 1, 0, o.residual, 0.0, std::nullopt, 0, condensed.sparse_solves, elapsed()});
    summary.indicator = std::max(summary.indicator, o.residual);
    if (callback && !callback(summary.history.back())) {
      summary.termination = Termination::StoppedByCallback;
      break;
    }
  }
  summary.iterations = static_cast<int>(summary.history.size());
  summary.wall_s = elapsed();
  if (summary.termination != Termination::NumericalIssue) summary.message = describeSuccess(summary, m, totals);
  return result;
}

}  // namespace stc
