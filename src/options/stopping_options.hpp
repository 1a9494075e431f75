#pragma once
// When an iterative strategy stops (docs/method.md §2): on the estimate of the true error, at an
// iteration cap, or when the indicator stagnates. Part of the options of every iterative strategy.
#include "stcontact/options/option_fields.hpp"

namespace stc {

struct StoppingOptions {
  /// On the estimate of the true error (src/solver/error_estimate.hpp; docs/method.md §2), tested
  /// after every iteration (every relaxation for FAS).
  double tolerance = 1e-6;
  /// Iterations (relaxations for FAS) at most: LATIN converges linearly and the seed scene needs a few
  /// hundred at 1e-6; the hard cases that fail do not converge in 2000 either (docs/hard_cases.md).
  int max_iterations = 2000;
  /// Stop as stagnated when the indicator has not decreased by 1 % over this many iterations (0:
  /// never).
  int stagnation_window = 500;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    visit("tolerance", o.tolerance, positive());
    visit("max_iterations", o.max_iterations, atLeast(1));
    visit("stagnation_window", o.stagnation_window, atLeast(0), Exposure::Library);
  }
  void validate() const { validateFields(*this, "stopping"); }
};

}  // namespace stc
