#pragma once
// The threads behind stc::parallelFor (src/core/threads.hpp): workers started once and kept, so
// that a parallel loop costs a wake-up, not a thread start. Idle workers spin briefly, then sleep
// (std::atomic::wait): on a machine shared with other processes a spinning worker takes the core
// that a busy thread needs. libgomp's default (spin ~300 000 times before sleeping, settable only
// through OMP_WAIT_POLICY before the program starts) made 2-thread fas-apriori solves 7x slower
// than 1 thread on the shared 2-core machine; OMP_WAIT_POLICY=passive did not (docs/threads.md).
#include <atomic>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace stc::detail {

class WorkerPool {
 public:
  /// The process's pool (grows on demand, joined at exit).
  static WorkerPool& instance();
  ~WorkerPool();

  /// Calls task(t) for t = 0 … threads − 1 at once: t = 0 on the calling thread, the others on
  /// workers; returns when all have returned. One run at a time (others wait). `task` must not
  /// throw (parallelFor catches inside it).
  void run(int threads, const std::function<void(int)>& task);

  /// True on a worker, and on the calling thread during run().
  static bool insideRun();

 private:
  WorkerPool() = default;
  void work(int index, unsigned seen);
  void grow(int workers);

  std::mutex run_mutex_;
  std::vector<std::thread> workers_;
  const std::function<void(int)>* task_ = nullptr;  ///< written before generation_ is raised
  int threads_ = 0;                                   ///< participants of the current run
  std::atomic<unsigned> generation_{0};               ///< raised once per run (and to stop)
  std::atomic<int> remaining_{0};                     ///< workers that have not finished the run
  bool stop_ = false;
};

}  // namespace stc::detail
