#pragma once
// The program's progress (studies/progress.hpp): a line redrawn on a terminal (stderr is a tty), at
// most every 0.2 s; never with --quiet. Notes (one line per strategy or sweep value) go to stdout
// unless --quiet.
#include <chrono>
#include <string>

#include "stcontact/studies/progress.hpp"

namespace stc::cli {

class TerminalProgress : public ProgressReporter {
 public:
  explicit TerminalProgress(bool quiet);
  IterationCallback begin(const std::string& label) override;
  void end() override;
  void note(const std::string& line) override;

 private:
  bool quiet_;
  bool tty_;
  std::string label_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace stc::cli
