#include "src/solver/contact_law_check.hpp"

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

Scales historyScales(const Problem& problem, const InterfaceHistory& h) {
  Scales s;
  const int nc = h.numContactNodes();
  s.v = h.v.size() > 0 ? h.v.cwiseAbs().maxCoeff() : 0.0;
  for (int k = 0; k < h.numSteps(); ++k)
    for (int i = 0; i < nc; ++i) {
      s.force = std::max(s.force, std::abs(h.lambda(2 * i, k)));
      s.gap = std::max(s.gap, problem.contact.initial_gap[i] + h.v(2 * i, k));
    }
  return s;
}

}  // namespace

double ContactLawViolation::max() const {
  return std::max({penetration, negative_pressure, complementarity, cone, stick_slip, slip_direction});
}

ContactLawViolation checkContactLaw(const Problem& problem, const InterfaceHistory& history) {
  const Scales sc = historyScales(problem, history);
  const double mu = problem.contact.friction;
  ContactLawViolation out;
  for (int k = 0; k < history.numSteps(); ++k)
    for (int i = 0; i < history.numContactNodes(); ++i) {
      const double ln = history.lambda(2 * i, k), lt = history.lambda(2 * i + 1, k);
      const double g = problem.contact.initial_gap[i] + history.v(2 * i, k);
      const double s = history.v(2 * i + 1, k) - (k > 0 ? history.v(2 * i + 1, k - 1) : 0.0);
      out.penetration = std::max(out.penetration, relative(std::max(-g, 0.0), sc.v));
      out.negative_pressure = std::max(out.negative_pressure, relative(std::max(-ln, 0.0), sc.force));
      out.complementarity = std::max(out.complementarity, relative(std::abs(g * ln), sc.gap * sc.force));
      out.cone = std::max(out.cone, relative(std::max(std::abs(lt) - mu * ln, 0.0), sc.force));
      const double inside = relative(std::max(mu * ln - std::abs(lt), 0.0), sc.force);
      out.stick_slip = std::max(out.stick_slip, std::min(relative(std::abs(s), sc.v), inside));
      out.slip_direction = std::max(out.slip_direction, relative(std::max(lt * s, 0.0), sc.force * sc.v));
    }
  return out;
}

}  // namespace stc
