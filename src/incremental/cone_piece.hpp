#pragma once
// The Alart–Curnier cone law at one node (the equations in cone_newton.hpp's header): its residual F
// and the piece it lies on, with what the slip piece's linearisation needs (ξ̂, q). Both forms of the
// incremental solver evaluate the law through it, with their own ρ: the interface form (ConeLaw,
// ρ from the node's Delassus block) and the whole-body form (WholeBodyLaw, ρ from the node's
// stiffness).
#include <Eigen/Core>

#include "stcontact/contact/contact_state.hpp"

namespace stc {

/// A node's tangential part (d − 1 = 1 or 2 entries), on the stack: the law runs for every node at
/// every evaluation of the march.
using Tangent = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 2, 1>;

struct ConePiece {
  ContactState state = ContactState::Open;
  double F_n = 0.0;  ///< open: λ_n; closed: ρ_n g
  Tangent F_t;       ///< open: λ_t; stick: ρ_t s; slip: λ_t − μ λ̂_n ξ̂
  Tangent unit;      ///< slip: ξ̂ = ξ / |ξ|, ξ = λ_t − ρ_t s
  double q = 0.0;    ///< slip: μ λ̂_n / |ξ|
};

/// The law at a node with forces (λ_n, λ_t), gap g = g0 + v_n and slip increment s = v_t(t_k) − v_t(t_{k−1}):
///   λ̂_n = λ_n − ρ_n g ≤ 0: open;  else |ξ| ≤ μ λ̂_n: stick;  else slip.
inline ConePiece conePiece(double lambda_n, const Tangent& lambda_t, double g, const Tangent& s, double rho_n,
                           double rho_t, double mu) {
  ConePiece p;
  const double hat_n = lambda_n - rho_n * g;
  if (!(hat_n > 0.0)) {  // open (also a node with no ρ yet and g ≥ 0: ρ_n = 0, λ = 0)
    p.F_n = lambda_n;
    p.F_t = lambda_t;
    return p;
  }
  const Tangent xi = lambda_t - rho_t * s;
  const double radius = mu * hat_n, norm = xi.norm();
  p.F_n = rho_n * g;
  if (norm <= radius) {
    p.state = ContactState::Stick;
    p.F_t = rho_t * s;
    return p;
  }
  p.state = ContactState::Slip;
  p.unit = xi / norm;
  p.q = radius / norm;
  p.F_t = lambda_t - radius * p.unit;
  return p;
}

}  // namespace stc
