#include "stcontact/core/interruption.hpp"

#include <pthread.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <utility>
#include <cstdio>
#include <map>
#include <mutex>
#include <thread>

namespace stc {
namespace {

std::atomic<int> requested{-1};  // −1: none; otherwise the signal (0: a caller's request)
static_assert(std::atomic<int>::is_always_lock_free, "a flag a signal handler may set");
std::atomic<bool> reported{false};  // the stop's message printed (once, by one thread)

std::mutex cleanup_mutex;
std::map<long, std::vector<std::filesystem::path>>& cleanups() {
  static std::map<long, std::vector<std::filesystem::path>> registered;
  return registered;
}
long next_cleanup = 0;

const char* signalName(int signal) {
  return signal == SIGTERM ? "SIGTERM" : signal == SIGHUP ? "SIGHUP" : "SIGINT";
}

// The signals' thread: the first signal requests the stop; a run that has not ended after the
// grace is ended here, its registered paths removed first (a second signal ends it at once).
void waitForSignals(sigset_t set) {
  int signal = 0;
  if (sigwait(&set, &signal) != 0) return;
  requestInterruption(signal);
  timespec grace{static_cast<time_t>(kStopGrace), static_cast<long>((kStopGrace - static_cast<long>(kStopGrace)) * 1e9)};
  sigtimedwait(&set, nullptr, &grace);  // the grace, or a second signal
  const int status = reportStopAndExitStatus();
  {
    const std::lock_guard<std::mutex> lock(cleanup_mutex);
    std::error_code ec;
    for (const auto& [id, paths] : cleanups())
      for (const std::filesystem::path& path : paths) std::filesystem::remove_all(path, ec);
  }
  std::fflush(nullptr);
  _exit(status);
}

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

namespace {
thread_local std::function<bool()> stop_probe;  // the thread's StopProbe's, or none
}  // namespace

StopProbe::StopProbe(std::function<bool()> keep_going) : previous_(std::move(stop_probe)) {
  stop_probe = std::move(keep_going);
}

StopProbe::~StopProbe() { stop_probe = std::move(previous_); }

bool keepGoing() { return !interruptionRequested() && (!stop_probe || stop_probe()); }

void stopPoint() {
  if (!keepGoing()) throw Interrupted();
}

void stopOnSignals() {
  // A signal ignored when the program starts is discarded even when blocked, and sigwait would never
  // see it: SIGINT and SIGTERM get their default disposition back (a shell starts background jobs
  // with SIGINT ignored); SIGHUP stays ignored under nohup, which asks for exactly that.
  sigset_t set;
  sigemptyset(&set);
  struct sigaction current {};
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    sigaction(signal, nullptr, &current);
    if (signal == SIGHUP && current.sa_handler == SIG_IGN) continue;
    struct sigaction fallback {};
    fallback.sa_handler = SIG_DFL;
    sigemptyset(&fallback.sa_mask);
    sigaction(signal, &fallback, nullptr);
    sigaddset(&set, signal);
  }
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  std::thread(waitForSignals, set).detach();
}

int reportStopAndExitStatus() {
  if (reported.exchange(true))
    for (;;) pause();  // the other thread reports and ends the process
  const int signal = interruptionSignal() ? interruptionSignal() : SIGINT;
  std::fprintf(stderr, "stopped by %s: nothing written, the output folder is as it was before the run\n",
               signalName(signal));
  std::fflush(stderr);
  return 128 + signal;
}

StopCleanup::StopCleanup(std::vector<std::filesystem::path> paths) {
  const std::lock_guard<std::mutex> lock(cleanup_mutex);
  id_ = next_cleanup++;
  cleanups()[id_] = std::move(paths);
}

StopCleanup::~StopCleanup() {
  if (id_ < 0) return;
  const std::lock_guard<std::mutex> lock(cleanup_mutex);
  cleanups().erase(id_);
}

}  // namespace stc
