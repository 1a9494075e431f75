#pragma once
// Threads for the work that is independent (docs/threads.md): the LATIN local stage over contact
// nodes (docs/method.md §2: "embarrassingly parallel over nodes") and the global stage over blocks of
// instants (one right-hand side per instant, the factor only read). A pool of workers started once
// (src/core/worker_pool.hpp). The count is the calling thread's: a ThreadCountScope on this thread,
// else the process-wide one (the command line's --threads, STC_THREADS), so that two solves on two
// threads (the Python module's threads=) each run with, and record, their own.
// Splitting never changes the arithmetic of an item, so results are bitwise those of one thread
// (tests/core/test_threads.cpp, tests/latin/test_latin_threads.cpp; docs/threads.md).
#include <functional>

namespace stc {

/// The built-in count when STC_THREADS is not set (docs/threads.md: what paid on the 2-core machine).
inline constexpr int kDefaultThreads = 2;

/// Threads used by parallelFor on the calling thread: the innermost ThreadCountScope's count on this
/// thread, else setThreadCount's value, else the environment variable STC_THREADS (an integer >= 1;
/// anything else throws InputError naming it), else kDefaultThreads.
int threadCount();
/// Entries of a dense field (rows × instants) from which a pass over it runs on threadCount()
/// threads: below, waking the pool's worker costs more than the split saves (measured on the FAS
/// coarse step, docs/threads.md, "Why the coarse step is threaded from 2^16 entries").
inline constexpr long long kThreadedFieldEntries = 1LL << 16;
/// threadCount() for a field of `entries` entries from kThreadedFieldEntries on, else 1.
int threadsForField(long long entries);
/// Sets the process-wide count (every thread without a ThreadCountScope). Throws InputError unless
/// 1 <= n <= maxThreadCount().
void setThreadCount(int n);
/// Four times the machine's hardware threads (at least 4): more threads than that only add switching
/// (and a thread count of 2³¹ − 1 started a pool the machine could not hold).
int maxThreadCount();

/// Sets the count of the calling thread for one scope and restores its previous one (a call of the
/// Python module, the FAS coarse step, tests, benchmarks); other threads keep theirs. Throws
/// InputError as setThreadCount does.
class ThreadCountScope {
 public:
  explicit ThreadCountScope(int n);
  ~ThreadCountScope();
  ThreadCountScope(const ThreadCountScope&) = delete;
  ThreadCountScope& operator=(const ThreadCountScope&) = delete;

 private:
  int previous_;  ///< this thread's scoped count before, 0 when none
};

/// Calls body(item, thread) once for every item in [0, count), on min(threads, count) threads
/// (thread in [0, threads): an index for per-thread workspaces; 0 is the calling thread). Items are
/// handed out one at a time, in order (items of unequal cost balance). After a body throws, no new
/// item starts; the first exception is rethrown here once all threads have stopped. Calling it
/// from inside a body throws std::logic_error.
void parallelFor(int count, int threads, const std::function<void(int item, int thread)>& body);

/// Calls body(begin, end) on `threads` contiguous ranges covering [0, count), as equal as possible
/// (static split: for many cheap items of equal cost, with no shared cache lines inside a range).
void parallelRanges(int count, int threads, const std::function<void(int begin, int end)>& body);

}  // namespace stc
