#include "validation/hysteresis_loop.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace stc::validation {
namespace {

// δ on the initial loading branch (instants 0 … quarter, Q increasing) at force q, by linear
// interpolation: f_FE, the finite element model's own initial loading curve.
double initialLoading(const HysteresisLoop& loop, double q) {
  for (int k = 0; k < loop.quarter; ++k)
    if (q <= loop.q[k + 1]) {
      const double s = (q - loop.q[k]) / (loop.q[k + 1] - loop.q[k]);
      return loop.delta[k] + s * (loop.delta[k + 1] - loop.delta[k]);
    }
  return loop.delta[loop.quarter];
}

// The δ of branch [k0, k1] (monotone in Q) where Q crosses 0, by linear interpolation.
double deltaAtZeroForce(const HysteresisLoop& loop, int k0, int k1) {
  for (int k = k0; k < k1; ++k)
    if ((loop.q[k] <= 0.0) != (loop.q[k + 1] <= 0.0)) {
      const double s = loop.q[k] / (loop.q[k] - loop.q[k + 1]);
      return loop.delta[k] + s * (loop.delta[k + 1] - loop.delta[k]);
    }
  ADD_FAILURE() << "Q does not change sign on the branch";
  return 0.0;
}

}  // namespace

HysteresisLoop hysteresisLoop(std::vector<double> q, std::vector<double> delta, int quarter) {
  HysteresisLoop loop;
  loop.q = std::move(q);
  loop.delta = std::move(delta);
  loop.quarter = quarter;
  const int extreme = quarter, closed = 5 * quarter;  // +δ*, then back to it
  if (static_cast<int>(loop.q.size()) <= closed || loop.delta.size() != loop.q.size()) {
    ADD_FAILURE() << "a loop needs 5 × " << quarter << " + 1 instants, got " << loop.q.size();
    return loop;
  }
  for (int k = extreme; k < closed; ++k)
    loop.area += 0.5 * (loop.q[k] + loop.q[k + 1]) * (loop.delta[k + 1] - loop.delta[k]);
  loop.area = std::abs(loop.area);
  loop.width = deltaAtZeroForce(loop, extreme, 3 * quarter) - deltaAtZeroForce(loop, 3 * quarter, closed);
  loop.q_star = loop.q[extreme];
  loop.closure = std::abs(loop.q[closed] - loop.q_star) / loop.q_star;
  const double delta_star = loop.delta[extreme];
  for (int k = extreme; k <= 3 * quarter; ++k)  // Masing: the unloading branch is f scaled by 2
    loop.masing = std::max(loop.masing, std::abs(delta_star - loop.delta[k] - 2.0 * initialLoading(loop, 0.5 * (loop.q_star - loop.q[k]))) / delta_star);
  return loop;
}

}  // namespace stc::validation
