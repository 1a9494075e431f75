#pragma once
// Progress line for long runs: shown on a terminal only (stderr is a tty), never with --quiet.
#include <chrono>
#include <string>

#include "src/solver/solve_summary.hpp"

namespace stc::cli {

class Progress {
 public:
  Progress(std::string label, bool enabled);
  /// An IterationCallback that redraws the line at most every 0.2 s; never stops the solve.
  IterationCallback callback();
  /// Clears the line.
  void done();

 private:
  std::string label_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace stc::cli
