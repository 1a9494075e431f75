#pragma once
// The program's progress (studies/progress.hpp), on standard error: on a terminal, one line redrawn
// at most every 0.2 s; otherwise (a batch log, a pipe) a plain line at most every
// --progress-interval seconds (default 5; 0: none), so that a long run's log shows it is alive and
// how far it is. Never with --quiet. Notes (one line per strategy or sweep value) go to stdout
// unless --quiet. Every iteration's line, every note and every line given to record() are kept,
// quiet or not, for the run folder's run.log (lines()).
#include <CLI/CLI.hpp>
#include <chrono>
#include <string>
#include <vector>

#include "stcontact/studies/progress.hpp"

namespace stc::cli {

/// Seconds between plain progress lines when standard error is not a terminal.
inline constexpr double kDefaultLogInterval = 5.0;

/// Adds --progress-interval S to `command`; InputError for a negative or non-finite S.
CLI::Option* addProgressIntervalOption(CLI::App& command);

class TerminalProgress : public ProgressReporter {
 public:
  explicit TerminalProgress(bool quiet);
  IterationCallback begin(const std::string& label) override;
  void end() override;
  void note(const std::string& line) override;
  /// "progress: <label>: <line>" on standard error at once (no interval: a phase line is rare and
  /// announces a long silence), unless quiet or --progress-interval 0 in a log; kept for run.log
  /// either way.
  void phase(const std::string& label, const std::string& line) override;
  /// Keeps `line` for the log without printing it (a warning printed elsewhere, the final report).
  void record(std::string line) { lines_.push_back(std::move(line)); }
  /// What the run showed or would have shown: one line each, in order.
  const std::vector<std::string>& lines() const { return lines_; }

 private:
  /// The record's fields: iteration, indicator, estimate, true error, rank, seconds.
  std::string describe(const IterationRecord& r) const;

  bool quiet_;
  bool tty_;
  std::string label_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_;
  std::vector<std::string> lines_;
};

}  // namespace stc::cli
