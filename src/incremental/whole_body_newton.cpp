#include "stcontact/incremental/whole_body_newton.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/incremental/cone_piece.hpp"

namespace stc {

ContactRowDofs contactRowDofs(const Eigen::SparseMatrix<double>& B) {
  ContactRowDofs out{std::vector<int>(static_cast<std::size_t>(B.rows()), -1), Eigen::VectorXd::Zero(B.rows())};
  for (Eigen::Index col = 0; col < B.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(B, col); it; ++it) {
      if (it.value() == 0.0) continue;
      int& dof = out.dof[static_cast<std::size_t>(it.row())];
      dof = dof == -1 ? static_cast<int>(col) : -2;
      out.coefficient[it.row()] = it.value();
    }
  return out;
}

std::string wholeBodyRefusal(const Problem& problem, const SpdSolver& stiffness) {
  const ContactInterface& c = problem.contact;
  if (!stiffness.holdsDofs())
    return "the " + stiffness.backend() + " backend cannot hold dofs (solver.linear = \"cg-gamg\" can)";
  if (c.isPair()) return "it needs a rigid obstacle, not two bodies in contact";
  if (!c.held_rows.empty()) return "it does not take held tangential rows (a symmetry plane at the contact)";
  const ContactRowDofs rows = contactRowDofs(c.B);
  std::vector<char> read(static_cast<std::size_t>(c.B.cols()), 0);
  for (std::size_t r = 0; r < rows.dof.size(); ++r)
    if (rows.dof[r] < 0 || read[static_cast<std::size_t>(rows.dof[r])]++)
      return "contact row " + std::to_string(r) +
             " does not read one free dof of its own (it needs an obstacle whose normal is an axis)";
  return {};
}

WholeBodyLaw::WholeBodyLaw(const Problem& problem, const SpdSolver& stiffness)
    : problem_(problem), contact_(problem.contact), stiffness_(stiffness), d_(problem.contact.dimension) {
  if (const std::string why = wholeBodyRefusal(problem, stiffness); !why.empty())
    throw InputError("solver.incremental_form = \"whole-body\": " + why);
  K_ = problem.stiffness_free.selfadjointView<Eigen::Lower>();
  ContactRowDofs rows = contactRowDofs(contact_.B);
  dof_ = std::move(rows.dof);
  coefficient_ = std::move(rows.coefficient);
  const int nc = contact_.size();
  rho_n_.resize(nc);
  rho_t_ = Eigen::VectorXd::Zero(nc);
  const auto rho = [&](int r) {
    const int dof = dof_[static_cast<std::size_t>(r)];
    return K_.coeff(dof, dof) / (coefficient_[r] * coefficient_[r]);
  };
  for (int i = 0; i < nc; ++i) {
    rho_n_[i] = rho(d_ * i);
    for (int a = 1; a < d_; ++a) rho_t_[i] += rho(d_ * i + a) / (d_ - 1);
  }
  rho_max_ = nc > 0 ? std::max(rho_n_.maxCoeff(), rho_t_.maxCoeff()) : 0.0;
  u_ = Eigen::VectorXd::Zero(problem.numFreeDofs());
}

// The Alart–Curnier residual of cone_newton.hpp node by node (cone_piece.hpp), with this form's ρ.
WholeBodyLaw::Evaluation WholeBodyLaw::evaluate(const Eigen::VectorXd& lambda, const Eigen::VectorXd& v,
                                                const Eigen::VectorXd& v_previous) const {
  const int nc = contact_.size(), dt = d_ - 1;
  Evaluation e{Eigen::VectorXd(lambda.size()), std::vector<ContactState>(static_cast<std::size_t>(nc)),
               Eigen::MatrixXd::Zero(dt, nc), Eigen::VectorXd::Zero(nc)};
  for (int i = 0; i < nc; ++i) {
    const int n = d_ * i, t = n + 1;
    const Tangent s = v.segment(t, dt) - v_previous.segment(t, dt);
    const ConePiece p = conePiece(lambda[n], lambda.segment(t, dt), contact_.initial_gap[i] + v[n], s, rho_n_[i],
                                  rho_t_[i], contact_.friction);
    e.piece[static_cast<std::size_t>(i)] = p.state;
    e.F[n] = p.F_n;
    e.F.segment(t, dt) = p.F_t;
    if (p.state == ContactState::Slip) {
      e.unit.col(i) = p.unit;
      e.q[i] = p.q;
    }
  }
  return e;
}

// Row a of node i: Σ_b (I − qP)_ab K(t_b, :) / b_t_b − μ ξ̂_a K(n, :) / b_n + q ρ_t Σ_b P_ab b_t_b e_{t_b},
// right-hand side Σ_b (I − qP)_ab f_t_b / b_t_b − μ ξ̂_a f_n / b_n + q ρ_t Σ_b P_ab v_t_b(t_{k−1}).
void WholeBodyLaw::addSlipRows(int i, const Evaluation& e, const Eigen::VectorXd& f,
                               const Eigen::VectorXd& v_previous, std::vector<Eigen::Triplet<double>>& rows,
                               std::vector<int>& dofs, Eigen::VectorXd& b) const {
  const int dt = d_ - 1, n = d_ * i;
  const Eigen::VectorXd unit = e.unit.col(i);
  const Eigen::MatrixXd P = Eigen::MatrixXd::Identity(dt, dt) - unit * unit.transpose();
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(dt, dt) - e.q[i] * P, C = e.q[i] * rho_t_[i] * P;
  const auto addRow = [&](int row, int source, double weight) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(K_, dof_[static_cast<std::size_t>(source)]); it; ++it)
      rows.emplace_back(row, static_cast<int>(it.col()), weight * it.value());
  };
  for (int a = 0; a < dt; ++a) {
    const int row = static_cast<int>(dofs.size()), dof = dof_[static_cast<std::size_t>(n + 1 + a)];
    const double normal_weight = -contact_.friction * unit[a] / coefficient_[n];
    double rhs = normal_weight * f[dof_[static_cast<std::size_t>(n)]];
    addRow(row, n, normal_weight);
    for (int c = 0; c < dt; ++c) {
      const int r = n + 1 + c, dof_c = dof_[static_cast<std::size_t>(r)];
      addRow(row, r, A(a, c) / coefficient_[r]);
      rows.emplace_back(row, dof_c, C(a, c) * coefficient_[r]);
      rhs += A(a, c) * f[dof_c] / coefficient_[r] + C(a, c) * v_previous[r];
    }
    dofs.push_back(dof);
    b[dof] = rhs;
  }
}

Eigen::VectorXd WholeBodyLaw::solveActiveSet(const Evaluation& e, const Eigen::VectorXd& f,
                                             const Eigen::VectorXd& v_previous) {
  const auto rows = static_cast<int>(dof_.size());
  std::vector<int> held;
  Eigen::VectorXd b = f, x0 = u_;
  std::vector<Eigen::Triplet<double>> slip_rows;
  SpdSolver::ReplacedRows replaced;
  for (int i = 0; i < contact_.size(); ++i) {
    const ContactState piece = e.piece[static_cast<std::size_t>(i)];
    if (piece == ContactState::Open) continue;
    const int n = d_ * i;
    held.push_back(dof_[static_cast<std::size_t>(n)]);  // g = 0
    x0[held.back()] = -contact_.initial_gap[i] / coefficient_[n];
    if (piece == ContactState::Slip) {
      addSlipRows(i, e, f, v_previous, slip_rows, replaced.dofs, b);
      continue;
    }
    for (int r = n + 1; r < n + d_; ++r) {  // s = 0
      held.push_back(dof_[static_cast<std::size_t>(r)]);
      x0[held.back()] = v_previous[r] / coefficient_[r];
    }
  }
  std::sort(held.begin(), held.end());
  replaced.rows.resize(static_cast<Eigen::Index>(replaced.dofs.size()), K_.cols());
  replaced.rows.setFromTriplets(slip_rows.begin(), slip_rows.end());
  u_ = stiffness_.solveHeld(b, held, x0, replaced);
  ++solves_;
  Eigen::VectorXd residual = K_ * u_ - f;
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(rows);
  for (int r = 0; r < rows; ++r)
    if (e.piece[static_cast<std::size_t>(r / d_)] != ContactState::Open)
      lambda[r] = residual[dof_[static_cast<std::size_t>(r)]] / coefficient_[r];
  for (int dof : held) residual[dof] = 0.0;
  for (int dof : replaced.dofs) residual[dof] = 0.0;
  noise_ = residual.norm();  // the equilibrium's residual on the rows solved for
  return lambda;
}

InstantOutcome WholeBodyLaw::solve(int k, const Eigen::VectorXd& lambda_previous, const Eigen::VectorXd& v_previous,
                                   double tolerance, int max_iterations) {
  const Eigen::VectorXd f = problem_.load(k);
  InstantOutcome out;
  const Eigen::VectorXd u_previous = u_;
  predict(k, lambda_previous, out);
  Evaluation e = evaluate(out.lambda, out.v, v_previous);  // the predicted active set
  for (;;) {
    if (out.iterations == max_iterations) {
      out.failure = "no convergence";
      break;
    }
    const Eigen::VectorXd u_from = u_;
    const double phi0 = e.F.norm();
    out.lambda = solveActiveSet(e, f, v_previous);
    out.v = contact_.B * u_;
    ++out.iterations;
    e = evaluate(out.lambda, out.v, v_previous);
    bool done = stops(out, e, v_previous, tolerance);
    if (!done) {
      backtrack(u_from, phi0, f, v_previous, out, e);
      done = stops(out, e, v_previous, tolerance);
    }
    if (!e.F.allFinite() || !std::isfinite(out.residual)) {
      out.failure = "non-finite residual";
      break;
    }
    if (done) {
      out.converged = true;
      before_ = {u_previous, lambda_previous};
      return out;
    }
  }
  u_ = u_previous;
  return out;
}

// Whether the instant stops at out's iterate: ‖F‖∞ ≤ max(tolerance S_k, kNoiseMargin ν) (header),
// out.residual set to ‖F‖∞ / S_k.
bool WholeBodyLaw::stops(InstantOutcome& out, const Evaluation& e, const Eigen::VectorXd& v_previous,
                         double tolerance) const {
  const double scale =
      std::max(out.lambda.lpNorm<Eigen::Infinity>(), rho_max_ * (out.v - v_previous).lpNorm<Eigen::Infinity>());
  const double r = e.F.lpNorm<Eigen::Infinity>();
  out.residual = scale > 0.0 ? r / scale : (r > 0.0 ? INFINITY : 0.0);
  return r <= std::max(tolerance * scale, kNoiseMargin * noise_);
}

// newton_instant.hpp's globalisation on this form's unknown u: when the step to the active set's
// solution does not decrease ‖F‖₂ by the Armijo factor, the points u_from + α (u − u_from), α = 2⁻¹,
// 2⁻², …, 2⁻¹², with their forces read off the equilibrium, λ = (K_ff u − f)_d / b (affine in u: two
// products with K_ff, no solve); the first that decreases it is taken, else the full step. A step
// that ends the instant is taken whole (at the noise of the solves ‖F‖ need not fall more). Without
// it the active sets of a coarse grid can cycle: the fretting history on 201 instants stalled at
// instant 149 (t = 0.745, the tangential motion reversing in gross slip) with ‖F‖ 0.03 after 50
// iterations at divisions 8, 12 and 16.
void WholeBodyLaw::backtrack(const Eigen::VectorXd& u_from, double phi0, const Eigen::VectorXd& f,
                             const Eigen::VectorXd& v_previous, InstantOutcome& out, Evaluation& e) {
  if (!std::isfinite(phi0) || e.F.norm() <= (1.0 - newton::kArmijo) * phi0) return;
  const auto rows = static_cast<Eigen::Index>(dof_.size());
  const Eigen::VectorXd du = u_ - u_from, r_from = K_ * u_from - f, dr = K_ * du;
  double alpha = 1.0;
  for (int h = 1; h <= newton::kMaxHalvings; ++h) {
    alpha *= 0.5;
    const Eigen::VectorXd u = u_from + alpha * du;
    Eigen::VectorXd lambda(rows);
    for (Eigen::Index r = 0; r < rows; ++r) {
      const int dof = dof_[static_cast<std::size_t>(r)];
      lambda[r] = (r_from[dof] + alpha * dr[dof]) / coefficient_[r];
    }
    const Eigen::VectorXd v = contact_.B * u;
    Evaluation trial = evaluate(lambda, v, v_previous);
    if (trial.F.norm() <= (1.0 - newton::kArmijo * alpha) * phi0) {
      u_ = u;
      out.lambda = std::move(lambda);
      out.v = v;
      e = std::move(trial);
      out.halvings += h;
      return;
    }
  }
  ++out.fallbacks;  // the full step kept
}

// The linear extrapolation from instants k − 2 and k − 1 (instant k − 1 alone at k ≤ 1): u_, and
// out's λ and v = B u_.
void WholeBodyLaw::predict(int k, const Eigen::VectorXd& lambda_previous, InstantOutcome& out) {
  out.lambda = lambda_previous;
  if (k >= 2 && before_.u.size() == u_.size()) {
    const std::vector<double>& t = problem_.times;
    const double ratio = (t[k] - t[k - 1]) / (t[k - 1] - t[k - 2]);
    u_ += ratio * (u_ - before_.u);
    out.lambda += ratio * (lambda_previous - before_.lambda);
  }
  out.v = contact_.B * u_;
}

}  // namespace stc
