#pragma once
// Elapsed time: seconds on the steady clock, the one way the code measures how long something took
// (a preparation, a reference, the writing, a whole run).
#include <chrono>

namespace stc {

/// Seconds from `start` to now on the steady clock.
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace stc
