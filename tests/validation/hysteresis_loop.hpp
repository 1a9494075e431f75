#pragma once
// A force–displacement loop Q(δ) measured on a fretting cycle and the quantities Mindlin's theory
// predicts for it (K. L. Johnson, Contact Mechanics, 1985, §7.4): the bodies pressed, then driven
// from 0 to +δ* in `quarter` instants, to −δ* in 2 × quarter, back to +δ* in 2 × quarter.
#include <vector>

namespace stc::validation {

struct HysteresisLoop {
  std::vector<double> q, delta;  ///< Q and δ at every instant from the end of pressing
  int quarter = 0;               ///< instants from 0 to +δ*
  double q_star = 0.0;           ///< Q at +δ*
  double area = 0.0;             ///< |∮ Q dδ| over the closed cycle (trapezoidal rule)
  double width = 0.0;            ///< δ where Q = 0 unloading minus δ where Q = 0 reloading
  double closure = 0.0;          ///< |Q at the end − Q*| / Q*
  /// Masing's rule, δ* − δ_u(Q) = 2 f((Q* − Q)/2) with f the model's own initial loading curve:
  /// its largest violation on the unloading branch, relative to δ*.
  double masing = 0.0;
};

/// The loop's quantities from Q and δ at instants 0 … 5 × quarter after pressing.
HysteresisLoop hysteresisLoop(std::vector<double> q, std::vector<double> delta, int quarter);

}  // namespace stc::validation
