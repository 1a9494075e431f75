#include "stcontact/core/worker_pool.hpp"

namespace stc::detail {
namespace {

thread_local bool inside_run = false;

// Waits until value() != old: first yields the core a few times (a run's wake-up or end is often
// microseconds away), then sleeps in std::atomic::wait (a futex on Linux).
template <class T>
T awaitChange(const std::atomic<T>& value, T old) {
  for (int i = 0; i < 64; ++i) {
    const T now = value.load(std::memory_order_acquire);
    if (now != old) return now;
    std::this_thread::yield();
  }
  for (;;) {
    value.wait(old, std::memory_order_acquire);
    const T now = value.load(std::memory_order_acquire);
    if (now != old) return now;
  }
}

}  // namespace

WorkerPool& WorkerPool::instance() {
  static WorkerPool pool;
  return pool;
}

WorkerPool::~WorkerPool() {
  {
    const std::lock_guard lock(run_mutex_);
    stop_ = true;
    generation_.fetch_add(1, std::memory_order_release);
  }
  generation_.notify_all();
  for (auto& worker : workers_) worker.join();
}

bool WorkerPool::insideRun() { return inside_run; }

// A worker sees every generation exactly once: run() raises the next one only after every worker
// has reported the current one done (remaining_ counts all workers, participants or not).
void WorkerPool::work(int index, unsigned seen) {
  inside_run = true;
  for (;;) {
    seen = awaitChange(generation_, seen);
    if (stop_) return;
    if (index < threads_) (*task_)(index);
    if (remaining_.fetch_sub(1, std::memory_order_acq_rel) == 1) remaining_.notify_one();
  }
}

void WorkerPool::grow(int workers) {
  const unsigned current = generation_.load(std::memory_order_relaxed);  // not raised while we hold run_mutex_
  while (static_cast<int>(workers_.size()) < workers) {
    const int index = static_cast<int>(workers_.size()) + 1;
    workers_.emplace_back([this, index, current] { work(index, current); });
  }
}

void WorkerPool::run(int threads, const std::function<void(int)>& task) {
  const std::lock_guard lock(run_mutex_);
  grow(threads - 1);
  task_ = &task;
  threads_ = threads;
  remaining_.store(static_cast<int>(workers_.size()), std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  inside_run = true;
  task(0);
  inside_run = false;
  for (int left = remaining_.load(std::memory_order_acquire); left != 0;) left = awaitChange(remaining_, left);
}

}  // namespace stc::detail
