#include "stcontact/core/interruption.hpp"

#include <atomic>
#include <csignal>

namespace stc {
namespace {

std::atomic<int> requested{-1};  // −1: none; otherwise the signal (0: a caller's request)
static_assert(std::atomic<int>::is_always_lock_free, "a flag a signal handler may set");

extern "C" void onSignal(int signal) { requestInterruption(signal); }

}  // namespace

void requestInterruption(int signal) noexcept {
  int none = -1;
  requested.compare_exchange_strong(none, signal);  // the first request is the one reported
}

void clearInterruption() noexcept { requested.store(-1); }

bool interruptionRequested() noexcept { return requested.load() >= 0; }

int interruptionSignal() noexcept { return requested.load() > 0 ? requested.load() : 0; }

void throwIfInterrupted() {
  if (interruptionRequested()) throw Interrupted();
}

void stopOnSignals() {
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace stc
