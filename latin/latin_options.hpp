#pragma once
// Options of the LATIN solver (house style 2: plain struct, in-class defaults with a reason,
// validate() naming the field, its value and the rule broken).
namespace stc::latin {

struct LatinOptions {
  double tolerance = 1e-6;      ///< stop when the indicator η ≤ tolerance (docs/method.md §2)
  int max_iterations = 5000;    ///< LATIN converges linearly; the seed needs a few hundred at 1e-6
  double relaxation = 1.0;      ///< ω in (0, 1]: s ← ω s_new + (1 − ω) s_old (1: none)
  int stagnation_window = 500;  ///< stop as stagnated if η has not decreased by 1% over this many
                                ///< iterations (0: never)
  int block_size = 32;          ///< instants per multi-right-hand-side solve (memory n_free × block;
                                ///< 16–32 measured fastest on the seed scene, see spd_factor.cpp)

  void validate() const;  ///< throws InputError
};

}  // namespace stc::latin
