#pragma once
// The semismooth Newton iteration of the incremental solver at one instant (incremental_solver.hpp:
// convergence test, backtracking line search, full-step fallback), written once for any model of
// the contact law at an instant: the plane law with the dense Delassus operator
// (incremental_solver.cpp) and the Coulomb cone with lazily computed columns (cone_newton.hpp).
//
// A Model provides
//   Evaluation evaluate(const Eigen::VectorXd& lambda);     // with members F (residual) and v
//   bool newtonStep(const Eigen::VectorXd& lambda, const Evaluation&, Eigen::VectorXd& step);
//   double forceScale(const Eigen::VectorXd& lambda) const;  // S_k of incremental_solver.hpp
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace stc {

struct InstantOutcome {
  Eigen::VectorXd lambda;
  Eigen::VectorXd v;
  double residual = 0.0;  // final ‖F‖∞ / S_k
  int iterations = 0, halvings = 0, fallbacks = 0;
  bool converged = false;
  std::string failure;
};

/// The force scale S_k = max(‖λ‖∞, ρ_max ‖v_0(:, k)‖∞) of incremental_solver.hpp: the largest
/// contact force, or before any builds up, the force that would push a node back by the free motion.
inline double forceScale(const Eigen::VectorXd& lambda, double rho_max, const Eigen::VectorXd& v0) {
  return std::max(lambda.lpNorm<Eigen::Infinity>(), rho_max * v0.lpNorm<Eigen::Infinity>());
}

namespace newton {

inline constexpr double kArmijo = 1e-4;  // sufficient decrease of ‖F‖₂ along the step
inline constexpr int kMaxHalvings = 12;  // smallest step length tried: 2⁻¹²

// Backtracking on ‖F‖₂ from λ along `step`; full step when no length decreases it.
template <class Model, class Evaluation>
void lineSearch(Model& model, const Eigen::VectorXd& step, InstantOutcome& out, Evaluation& e) {
  const double phi0 = e.F.norm();
  Evaluation full = model.evaluate(out.lambda + step);
  double alpha = 1.0;
  Evaluation trial = full;
  for (int h = 0; h <= kMaxHalvings; ++h) {
    if (h > 0) trial = model.evaluate(out.lambda + alpha * step);
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

}  // namespace newton

/// Semismooth Newton at one instant from `start` until ‖F‖∞ ≤ tolerance · S_k, a failure, or
/// max_iterations steps.
template <class Model>
InstantOutcome solveInstantByNewton(Model& model, const Eigen::VectorXd& start, double tolerance, int max_iterations) {
  InstantOutcome out;
  out.lambda = start;
  auto e = model.evaluate(out.lambda);
  for (;; ++out.iterations) {
    const double scale = model.forceScale(out.lambda), r = e.F.template lpNorm<Eigen::Infinity>();
    out.residual = scale > 0.0 ? r / scale : (r > 0.0 ? INFINITY : 0.0);
    if (!e.F.allFinite() || !std::isfinite(out.residual)) {  // lpNorm's max can skip a NaN
      out.failure = "non-finite residual";
      break;
    }
    if (r <= tolerance * scale) {
      out.converged = true;
      break;
    }
    if (out.iterations == max_iterations) {
      out.failure = "no convergence";
      break;
    }
    Eigen::VectorXd step;
    if (!model.newtonStep(out.lambda, e, step)) {
      out.failure = "singular or non-finite Newton system";
      break;
    }
    newton::lineSearch(model, step, out, e);
  }
  out.v = std::move(e.v);
  return out;
}

}  // namespace stc
