#include "stcontact/core/threads.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/worker_pool.hpp"

namespace stc {
namespace {

constexpr int kUnset = 0;
std::atomic<int> chosen{kUnset};  // setThreadCount's, for every thread
thread_local int scoped = kUnset;  // the innermost ThreadCountScope's on this thread

int fromEnvironment() {
  const char* text = std::getenv("STC_THREADS");
  if (!text || !*text) return kDefaultThreads;
  char* end = nullptr;
  const long n = std::strtol(text, &end, 10);
  if (*end != '\0' || n < 1 || n > maxThreadCount())
    throw InputError(std::string("environment variable STC_THREADS = '") + text + "': must be an integer in [1, " +
                     std::to_string(maxThreadCount()) + "]");
  return static_cast<int>(n);
}

int checkedCount(int n) {
  const int most = maxThreadCount();
  if (n < 1 || n > most)
    throw InputError("thread count " + std::to_string(n) + ": must be in [1, " + std::to_string(most) + "] (four times the " +
                     std::to_string(most / 4) + " hardware threads of this machine; more only adds switching)");
  return n;
}

// A body that called parallelFor again would wait for the pool it runs on: refused.
void requireOutermost() {
  if (detail::WorkerPool::insideRun()) throw std::logic_error("stc::parallelFor called from inside a parallel body");
}

// The first exception of any thread, rethrown by the caller once all threads have stopped.
class FirstError {
 public:
  template <class Body>
  void guard(const Body& body) {
    if (failed_.load(std::memory_order_relaxed)) return;  // the loop is abandoned
    try {
      body();
    } catch (...) {
      const std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
      failed_.store(true, std::memory_order_relaxed);
    }
  }
  void rethrow() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr error_;
  std::atomic<bool> failed_{false};
};

}  // namespace

int threadCount() {
  if (scoped != kUnset) return scoped;
  const int n = chosen.load();
  if (n != kUnset) return n;
  static const int environment = fromEnvironment();
  return environment;
}

int threadsForField(long long entries) { return entries >= kThreadedFieldEntries ? threadCount() : 1; }

int maxThreadCount() { return 4 * static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

void setThreadCount(int n) { chosen.store(checkedCount(n)); }

ThreadCountScope::ThreadCountScope(int n) : previous_(scoped) { scoped = checkedCount(n); }

ThreadCountScope::~ThreadCountScope() { scoped = previous_; }

void parallelFor(int count, int threads, const std::function<void(int, int)>& body) {
  requireOutermost();
  threads = std::max(1, std::min(threads, count));
  if (threads == 1) {
    for (int i = 0; i < count; ++i) body(i, 0);
    return;
  }
  std::atomic<int> next{0};  // items are taken one at a time, in order
  FirstError error;
  detail::WorkerPool::instance().run(threads, [&](int thread) {
    for (int i; (i = next.fetch_add(1, std::memory_order_relaxed)) < count;) error.guard([&] { body(i, thread); });
  });
  error.rethrow();
}

void parallelRanges(int count, int threads, const std::function<void(int, int)>& body) {
  requireOutermost();
  threads = std::max(1, std::min(threads, count));
  if (threads == 1) {
    if (count > 0) body(0, count);
    return;
  }
  // Range r is [r·count/threads, (r+1)·count/threads): sizes differ by at most one.
  const auto bound = [&](int r) { return static_cast<int>(static_cast<long>(r) * count / threads); };
  FirstError error;
  detail::WorkerPool::instance().run(threads, [&](int r) { error.guard([&] { body(bound(r), bound(r + 1)); }); });
  error.rethrow();
}

}  // namespace stc
