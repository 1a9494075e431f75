#include "src/cli/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace stc::cli {

Progress::Progress(std::string label, bool enabled)
    : label_(std::move(label)), enabled_(enabled && isatty(STDERR_FILENO)) {}

IterationCallback Progress::callback() {
  return [this](const IterationRecord& r) {
    if (!enabled_) return true;
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

void Progress::done() {
  if (enabled_ && drawn_) std::fprintf(stderr, "\r\033[K");
  drawn_ = false;
}

}  // namespace stc::cli
