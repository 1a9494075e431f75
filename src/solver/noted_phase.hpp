#pragma once
// A phase of a solve outside its iterations, told through SolveInputs::phase_note: a line when it
// starts, one with its sparse solves and seconds when it ends, and between them, for a phase that can
// last an hour (the incremental solver's Delassus columns at 10⁶ dofs on CG + GAMG, more than 25
// minutes on two ranks: docs/linear_solvers.md), a line of where it is at most once a minute. Two use
// it: the separated solvers' displacement after their last iteration (pgd/after_iteration.hpp) and
// the incremental solver's Delassus columns before its march (src/incremental/incremental_solver.cpp).
#include <cstdio>
#include <string>
#include <utility>

#include "stcontact/core/clock.hpp"
#include "stcontact/solver/solve_summary.hpp"

namespace stc {

class NotedPhase {
 public:
  /// Seconds between two lines of during().
  static constexpr double kDuringInterval = 60.0;

  /// Starts the phase's clock; `prefix` begins every line (e.g. "after the last iteration: ").
  NotedPhase(PhaseNote note, std::string prefix, double during_interval = kDuringInterval)
      : note_(std::move(note)),
        prefix_(std::move(prefix)),
        during_interval_(during_interval),
        started_(std::chrono::steady_clock::now()),
        last_line_(started_) {}
  /// Tells "<prefix><what>".
  void begin(const std::string& what) const {
    if (note_) note_(prefix_ + what);
  }
  /// Tells "<prefix><what>, <seconds> s" when `during_interval` seconds have passed since the start
  /// or since its last line; else nothing.
  void during(const std::string& what) {
    if (!note_ || secondsSince(last_line_) < during_interval_) return;
    last_line_ = std::chrono::steady_clock::now();
    note_(prefix_ + what + ", " + formattedSeconds());
  }
  /// Tells "<prefix><solves> sparse solves, <seconds> s" when the phase solved anything.
  void end(long solves) const {
    if (!note_ || solves == 0) return;
    note_(prefix_ + std::to_string(solves) + " sparse solves, " + formattedSeconds());
  }

 private:
  std::string formattedSeconds() const {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.1f s", secondsSince(started_));
    return seconds;
  }

  PhaseNote note_;
  std::string prefix_;
  double during_interval_;
  std::chrono::steady_clock::time_point started_;
  std::chrono::steady_clock::time_point last_line_;
};

}  // namespace stc
