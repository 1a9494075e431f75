#include "stcontact/solver/contact_law_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stc {
namespace {

// x / scale, with 0/0 = 0 and x/0 = +∞ for x > 0.
double relative(double x, double scale) {
  if (scale > 0.0) return x / scale;
  return x > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
}

struct Scales {
  double v = 0.0, force = 0.0, gap = 0.0;
};

Scales historyScales(const ContactInterface& c, const InterfaceHistory& h) {
  Scales s;
  s.v = h.v.size() > 0 ? h.v.cwiseAbs().maxCoeff() : 0.0;
  for (int k = 0; k < h.numSteps(); ++k)
    for (int i = 0; i < c.size(); ++i) {
      s.force = std::max(s.force, std::abs(h.lambda(c.normalRow(i), k)));
      s.gap = std::max(s.gap, c.initial_gap[i] + h.v(c.normalRow(i), k));
    }
  return s;
}

// Node i at instant k: normal force, gap, tangential force and slip increment (vectors of d − 1).
struct NodeInstant {
  double ln, g;
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 2, 1> lt, s;  // at most 2 entries: no allocation
  NodeInstant(const ContactInterface& c, const InterfaceHistory& h, int i, int k) {
    const int n = c.normalRow(i), t = n + 1, d = c.dimension - 1;
    ln = h.lambda(n, k);
    g = c.initial_gap[i] + h.v(n, k);
    lt = h.lambda.col(k).segment(t, d);
    s = h.v.col(k).segment(t, d);
    if (k > 0) s -= h.v.col(k - 1).segment(t, d);
  }
};

}  // namespace

double ContactLawViolation::max() const {
  return std::max({penetration, negative_pressure, complementarity, cone, stick_slip, slip_direction});
}

ContactLawViolation checkContactLaw(const Problem& problem, const InterfaceHistory& history) {
  const ContactInterface& c = problem.contact;
  const Scales sc = historyScales(c, history);
  const double mu = c.friction;
  ContactLawViolation out;
  for (int k = 0; k < history.numSteps(); ++k)
    for (int i = 0; i < c.size(); ++i) {
      const NodeInstant x(c, history, i, k);
      const double lt = x.lt.norm(), s = x.s.norm();
      out.penetration = std::max(out.penetration, relative(std::max(-x.g, 0.0), sc.v));
      out.negative_pressure = std::max(out.negative_pressure, relative(std::max(-x.ln, 0.0), sc.force));
      out.complementarity = std::max(out.complementarity, relative(std::abs(x.g * x.ln), sc.gap * sc.force));
      out.cone = std::max(out.cone, relative(std::max(lt - mu * x.ln, 0.0), sc.force));
      const double inside = relative(std::max(mu * x.ln - lt, 0.0), sc.force);
      out.stick_slip = std::max(out.stick_slip, std::min(relative(s, sc.v), inside));
      // (|λ_t| |s| + λ_t·s) / 2: 0 when the force opposes the slip; max(λ_t s, 0) in 2D.
      out.slip_direction = std::max(out.slip_direction, relative(0.5 * (lt * s + x.lt.dot(x.s)), sc.force * sc.v));
    }
  return out;
}

}  // namespace stc
