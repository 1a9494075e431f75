#pragma once
// Options of `latin`: LATIN over the whole space-time grid (docs/method.md §2).
#include "stcontact/options/option_fields.hpp"
#include "stcontact/options/stopping_options.hpp"

namespace stc::latin {

struct LatinOptions {
  StoppingOptions stop;
  /// ω in (0, 1]: s ← ω s_new + (1 − ω) s_old (1: none).
  double relaxation = 1.0;
  /// Instants per multi-right-hand-side solve of the global stage (memory n_free × block; 16–32
  /// measured fastest on the seed scene, src/linalg/backends/cholmod_factor.cpp).
  int block_size = 32;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    StoppingOptions::fields(o.stop, visit);
    visit("relaxation", o.relaxation, inUnitHalfOpen());
    visit("block_size", o.block_size, atLeast(1), Exposure::Library);
  }
  void validate() const { validateFields(*this, "LATIN"); }
};

}  // namespace stc::latin
