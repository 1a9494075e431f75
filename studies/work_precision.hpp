#pragma once
// Work against precision of one strategy (docs/compare.md): the points of its runs (work spent so far, true
// error reached) and the statistics the comparison reports, e.g. the median over repeats of the
// time a strategy needs to first reach a true error of 1e-4 (docs/method.md §2 error).
#include <optional>
#include <string>
#include <vector>

#include "stcontact/solver/solve_summary.hpp"

namespace stc {

/// One recorded iteration of a run: the work spent since the solve was called, and the result.
struct WorkPoint {
  int iteration = 0;
  int relaxations = 0;          ///< fine LATIN relaxations so far
  long sparse_solves = 0;       ///< right-hand sides solved with a sparse factor so far
  double indicator = 0.0;       ///< the solver's own stopping indicator
  std::optional<double> error;  ///< true relative energy error, when known
  double wall_s = 0.0;          ///< seconds since the call to the solver (set-up included)
};

/// One timed run (repeat r = 1 … N) of a strategy.
struct TimedRun {
  int repeat = 1;
  std::vector<WorkPoint> points;
  double total_s = 0.0;  ///< the whole call, returning included
};

/// The first point whose true error is at most `target`, if any.
std::optional<WorkPoint> firstReaching(const std::vector<WorkPoint>& points, double target);

/// Median of `values` (mean of the two middle ones for an even count); throws std::invalid_argument
/// when empty.
double median(std::vector<double> values);

/// Copies the true error of `measured` (a run of the same deterministic solver with the error
/// measured at every iteration) onto `timed`, matching points by iteration number. Returns false,
/// and leaves the errors it cannot match empty, when the two runs differ: another iteration count,
/// or an indicator that differs by more than `relative_tolerance`.
bool copyErrors(const std::vector<WorkPoint>& measured, std::vector<WorkPoint>& timed,
                double relative_tolerance = 1e-9);

/// What the median repeat needs to first reach one target error.
struct Reach {
  double target = 0.0;
  int repeats_reached = 0;               ///< repeats that reached the target (all or none, normally)
  std::optional<double> wall_s;          ///< median over the repeats that reached it
  std::optional<double> relaxations;     ///< idem
  std::optional<double> sparse_solves;   ///< idem
};

Reach reachOf(const std::vector<TimedRun>& runs, double target);

/// The repeat whose total time is the median one (the lower middle for an even count): the curve
/// the plots draw. Throws std::invalid_argument when `runs` is empty.
int medianRepeat(const std::vector<TimedRun>& runs);

}  // namespace stc
