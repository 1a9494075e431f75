#pragma once
// Where a solve's records count from, when the solve is a part of a larger one: what the parts
// before it spent (the set-up's sparse solves, a solve on a sub-grid of instants, a first relaxation,
// earlier rounds on a contact zone) and the clock of the whole. The iteration monitor adds it to every
// record it stores and hands to the callback, so that a history chained from several parts reads as
// one solve's (iterations, relaxations and sparse solves so far; wall time since the whole solve
// began, the true-error measures left out); the summary's stages say what each part was. The one
// mechanism for every chained part (SolveInputs::origin).
#include <chrono>
#include <functional>
#include <optional>

#include "stcontact/solver/solve_summary.hpp"

namespace stc {

struct RecordOrigin {
  using Clock = std::chrono::steady_clock;
  int iterations = 0;
  int relaxations = 0;
  long sparse_solves = 0;
  /// Added to the clock's reading: minus the seconds the earlier parts spent measuring true errors.
  double wall_s = 0.0;
  /// Where the whole solve's clock started; none: where this solve's monitor starts.
  std::optional<Clock::time_point> clock;
  /// The Krylov iterations of the whole solve so far (set by stc::solve from the operators it solves
  /// with); none: 0 in every record.
  std::function<long long()> krylov;

  /// `r` counted from this origin (its wall time is the monitor's, read on `clock`).
  IterationRecord applied(IterationRecord r) const {
    r.iteration += iterations;
    r.relaxations += relaxations;
    r.sparse_solves += static_cast<int>(sparse_solves);
    if (krylov) r.krylov_iterations = krylov();
    return r;
  }
  /// The same origin with `solves` more sparse solves before the part (a stage's set-up).
  RecordOrigin afterSolves(long solves) const {
    RecordOrigin o = *this;
    o.sparse_solves += solves;
    return o;
  }
  /// The same origin, its clock started now unless the whole solve's was.
  RecordOrigin clocked() const {
    RecordOrigin o = *this;
    if (!o.clock) o.clock = Clock::now();
    return o;
  }
};

}  // namespace stc
