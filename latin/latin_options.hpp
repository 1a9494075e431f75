#pragma once
// Options of the LATIN solver (house style 2: plain struct, in-class defaults with a reason,
// validate() naming the field, its value and the rule broken; defaults: src/core/solver_settings.hpp).
#include "stcontact/core/solver_settings.hpp"

namespace stc::latin {

struct LatinOptions {
  double tolerance = defaults::tolerance;         ///< stop when the indicator η ≤ tolerance (docs/method.md §2)
  int max_iterations = defaults::max_iterations;  ///< LATIN converges linearly: a few hundred at 1e-6 on the seed
  double relaxation = 1.0;                        ///< ω in (0, 1]: s ← ω s_new + (1 − ω) s_old (1: none)
  /// Stop as stagnated if η has not decreased by 1% over this many iterations (0: never).
  int stagnation_window = defaults::stagnation_window;
  int block_size = defaults::block_size;  ///< instants per multi-right-hand-side solve

  void validate() const;  ///< throws InputError
};

}  // namespace stc::latin
