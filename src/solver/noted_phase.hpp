#pragma once
// A phase of a solve outside its iterations, told through SolveInputs::phase_note: a line when it
// starts and one with its sparse solves and seconds when it ends. Two use it: the separated solvers'
// displacement after their last iteration (pgd/after_iteration.hpp) and the incremental solver's
// Delassus columns before its march (src/incremental/incremental_solver.cpp).
#include <cstdio>
#include <string>
#include <utility>

#include "stcontact/core/clock.hpp"
#include "stcontact/solver/solve_inputs.hpp"

namespace stc {

class NotedPhase {
 public:
  /// Starts the phase's clock; `prefix` begins both lines (e.g. "after the last iteration: ").
  NotedPhase(PhaseNote note, std::string prefix)
      : note_(std::move(note)), prefix_(std::move(prefix)), started_(std::chrono::steady_clock::now()) {}
  /// Tells "<prefix><what>".
  void begin(const std::string& what) const {
    if (note_) note_(prefix_ + what);
  }
  /// Tells "<prefix><solves> sparse solves, <seconds> s" when the phase solved anything.
  void end(long solves) const {
    if (!note_ || solves == 0) return;
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.1f s", secondsSince(started_));
    note_(prefix_ + std::to_string(solves) + " sparse solves, " + seconds);
  }

 private:
  PhaseNote note_;
  std::string prefix_;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace stc
