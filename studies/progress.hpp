#pragma once
// What a study shows while it runs, passed in by the program that runs it: the command line draws a
// line on a terminal (cli/terminal_progress.hpp), the Python module shows nothing (its own callback
// sees the records). A study asks for one callback per run and ends the run when it returns.
#include <string>

#include "stcontact/solver/solve_summary.hpp"

namespace stc {

class ProgressReporter {
 public:
  virtual ~ProgressReporter() = default;
  /// A run named `label` starts: the callback its solver calls after every record (it never stops
  /// the run).
  virtual IterationCallback begin(const std::string& label) = 0;
  /// The run ended: clears what the callback drew.
  virtual void end() = 0;
  /// A line of result once an item of the study is done (a strategy, a value of a sweep).
  virtual void note(const std::string& line) = 0;
  /// A line from the run named `label` saying what it does outside its iterations
  /// (SolveInputs::phase_note: the lift after the last one).
  virtual void phase(const std::string& label, const std::string& line) = 0;
};

/// One run's progress: begins on construction, ends on destruction; no reporter, no progress.
class RunProgress {
 public:
  RunProgress(ProgressReporter* reporter, const std::string& label)
      : reporter_(reporter), label_(label), callback_(reporter ? reporter->begin(label) : IterationCallback{}) {}
  ~RunProgress() {
    if (reporter_) reporter_->end();
  }
  RunProgress(const RunProgress&) = delete;
  RunProgress& operator=(const RunProgress&) = delete;
  /// The callback to pass to the solver (empty without a reporter).
  const IterationCallback& callback() const { return callback_; }
  /// What to pass as SolveInputs::phase_note (empty without a reporter).
  PhaseNote phaseNote() const {
    if (!reporter_) return {};
    return [reporter = reporter_, label = label_](const std::string& line) { reporter->phase(label, line); };
  }
  /// Shows `record` (true: the run goes on); without a reporter, nothing.
  bool show(const IterationRecord& record) const { return !callback_ || callback_(record); }

 private:
  ProgressReporter* reporter_;
  std::string label_;
  IterationCallback callback_;
};

}  // namespace stc
