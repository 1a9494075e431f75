#include "stcontact/cli/terminal_progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "stcontact/core/interruption.hpp"

namespace stc::cli {

TerminalProgress::TerminalProgress(bool quiet) : quiet_(quiet), tty_(!quiet && isatty(STDERR_FILENO)) {}

IterationCallback TerminalProgress::begin(const std::string& label) {
  label_ = label;
  return [this](const IterationRecord& r) {
    if (interruptionRequested()) return false;  // SIGINT, SIGTERM: the solve stops at this iteration
    if (!tty_) return true;
    const auto now = std::chrono::steady_clock::now();
    if (drawn_ && now - last_ < std::chrono::milliseconds(200)) return true;
    last_ = now;
    drawn_ = true;
    std::fprintf(stderr, "\r\033[K%s: iteration %d  indicator %.3e", label_.c_str(), r.iteration, r.indicator);
    if (r.error) std::fprintf(stderr, "  error %.3e", *r.error);
    if (r.rank > 0) std::fprintf(stderr, "  rank %d", r.rank);
    std::fprintf(stderr, "  %.1f s", r.wall_s);
    std::fflush(stderr);
    return true;
  };
}

void TerminalProgress::end() {
  if (tty_ && drawn_) std::fprintf(stderr, "\r\033[K");
  drawn_ = false;
}

void TerminalProgress::note(const std::string& line) {
  if (!quiet_) std::cout << line << std::endl;
}

}  // namespace stc::cli
