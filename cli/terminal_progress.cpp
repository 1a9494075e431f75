#include "stcontact/cli/terminal_progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/interruption.hpp"

namespace stc::cli {
namespace {

double log_interval = kDefaultLogInterval;  // set once, from the command line, before any run

std::string formatted(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace

CLI::Option* addProgressIntervalOption(CLI::App& command) {
  return command
      .add_option_function<double>(
          "--progress-interval",
          [](double seconds) {
            if (!(seconds >= 0.0 && std::isfinite(seconds)))
              throw InputError("--progress-interval: " + formatted("%g", seconds) + " seconds: must be >= 0");
            log_interval = seconds;
          },
          "seconds between progress lines when standard error is not a terminal (a log, a pipe); 0: none "
          "(default " + formatted("%g", kDefaultLogInterval) + ")")
      ->type_name("S");
}

TerminalProgress::TerminalProgress(bool quiet) : quiet_(quiet), tty_(!quiet && isatty(STDERR_FILENO)) {}

std::string TerminalProgress::describe(const IterationRecord& r) const {
  std::string text = label_ + ": iteration " + std::to_string(r.iteration) + formatted("  indicator %.3e", r.indicator);
  if (std::isfinite(r.error_estimate)) text += formatted("  estimate %.3e", r.error_estimate);
  if (r.error) text += formatted("  error %.3e", *r.error);
  if (r.rank > 0) text += "  rank " + std::to_string(r.rank);
  return text + formatted("  %.1f s", r.wall_s);
}

IterationCallback TerminalProgress::begin(const std::string& label) {
  label_ = label;
  last_ = std::chrono::steady_clock::now();  // a log's first line comes one interval after the start
  return [this](const IterationRecord& r) {
    if (interruptionRequested()) return false;  // SIGINT, SIGTERM: the solve stops at this iteration
    lines_.push_back("progress: " + describe(r));
    if (quiet_ || (!tty_ && log_interval <= 0.0)) return true;
    const auto now = std::chrono::steady_clock::now();
    const std::chrono::duration<double> wait(tty_ ? 0.2 : log_interval);
    if ((tty_ ? drawn_ : true) && now - last_ < wait) return true;
    last_ = now;
    drawn_ = true;
    if (tty_) std::fprintf(stderr, "\r\033[K%s", describe(r).c_str());
    else std::fprintf(stderr, "progress: %s\n", describe(r).c_str());
    std::fflush(stderr);
    return true;
  };
}

void TerminalProgress::end() {
  if (tty_ && drawn_) std::fprintf(stderr, "\r\033[K");
  drawn_ = false;
}

void TerminalProgress::note(const std::string& line) {
  lines_.push_back(line);
  if (!quiet_) std::cout << line << std::endl;
}

void TerminalProgress::phase(const std::string& label, const std::string& line) {
  const std::string text = "progress: " + label + ": " + line;
  lines_.push_back(text);
  if (quiet_ || (!tty_ && log_interval <= 0.0)) return;
  if (tty_) std::fprintf(stderr, "\r\033[K%s\n", text.c_str());  // below the redrawn iteration line
  else std::fprintf(stderr, "%s\n", text.c_str());
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace stc::cli
