#pragma once
// Options of the two-level FAS with LATIN as smoother (docs/method.md §4; seed paper §4.1–4.2).
// The coarse space's own options (residual vectors, modes) belong to its BasisProvider, the block
// size of the solves to the latin::GlobalStage the caller builds.
namespace stc::fas {

/// How the coarse step starts from s̃ = (ũ, λ̃) (docs/method.md §4, "How the coarse step starts").
enum class CoarseStart {
  ZeroCorrection,     ///< (a) Δv̂ = 0, Δλ̂ = 0, taking v = Bũ (discards v̂ − Bũ)
  InterfaceMismatch,  ///< (b) Δv̂ = v̂ − Bũ, Δλ̂ = 0 (exact when the coarse space is the whole space)
};

struct FasOptions {
  double tolerance = 1e-6;        ///< on the fine-level LATIN indicator, tested after every relaxation
  int max_relaxations = 5000;     ///< fine relaxations in all (the cost unit of the seed's Figs. 4–5)
  int pre_relaxations = 1;        ///< ν1 >= 1: the seed's Figs. 4–5 use ν1 = ν2 = 1
  int post_relaxations = 1;       ///< ν2 >= 0
  int coarse_iterations = 15;     ///< i_C: coarse linear stage + fine local stage pairs (seed: 15)
  CoarseStart start = CoarseStart::ZeroCorrection;
  /// Safeguard: a coarse correction after which the next relaxation's indicator exceeds the one
  /// before the coarse step is rejected (the pre-coarse local stage is restored) and the next
  /// coarse steps are skipped for 1, 2, 4, … up to max_skip cycles while rejections repeat. Without
  /// it a poor coarse space (e.g. 10 modes + 5 residual vectors on the seed scene) can lock FAS in
  /// a 2-cycle at true error 0.1-0.2 (docs/compare_bases.md). Off: the seed's plain cycle.
  bool safeguard = true;
  int max_skip = 8;               ///< >= 1, longest run of skipped coarse steps
  int stagnation_window = 500;    ///< relaxations without a 1% decrease of η before giving up (0: never)

  void validate() const;  ///< throws InputError naming the field
};

}  // namespace stc::fas
