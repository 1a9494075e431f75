// stc::parallelFor / parallelRanges (src/core/threads.hpp): every item exactly once, ranges that
// tile [0, count), exceptions carried out of the threads, nesting refused, the count's rules (a
// scope sets the count of its own thread only).
#include <gtest/gtest.h>

#include <atomic>
#include <latch>
#include <stdexcept>
#include <thread>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/threads.hpp"

TEST(ParallelFor, VisitsEveryItemExactlyOnceWithAThreadIndexBelowTheCount) {
  for (int threads : {1, 2, 3, 8})
    for (int count : {0, 1, 2, 7, 100}) {
      std::vector<std::atomic<int>> visits(count);
      std::atomic<int> bad_thread{0};
      stc::parallelFor(count, threads, [&](int item, int thread) {
        ++visits[item];
        if (thread < 0 || thread >= threads) ++bad_thread;
      });
      for (int i = 0; i < count; ++i) EXPECT_EQ(visits[i].load(), 1) << "item " << i << ", threads " << threads;
      EXPECT_EQ(bad_thread.load(), 0);
    }
}

TEST(ParallelRanges, TileTheItemsContiguouslyWithSizesDifferingByAtMostOne) {
  for (int threads : {1, 2, 3, 8})
    for (int count : {0, 1, 2, 7, 101}) {
      std::vector<std::atomic<int>> visits(count);
      std::atomic<int> smallest{count + 1}, largest{-1};
      stc::parallelRanges(count, threads, [&](int begin, int end) {
        ASSERT_LE(begin, end);
        for (int i = begin; i < end; ++i) ++visits[i];
        int size = end - begin, s = smallest.load(), l = largest.load();
        while (size < s && !smallest.compare_exchange_weak(s, size)) {}
        while (size > l && !largest.compare_exchange_weak(l, size)) {}
      });
      for (int i = 0; i < count; ++i) EXPECT_EQ(visits[i].load(), 1);
      if (count > 0) EXPECT_LE(largest.load() - smallest.load(), 1) << count << " items, " << threads << " threads";
    }
}

TEST(ParallelFor, RethrowsAnExceptionOfABodyAfterTheThreadsStop) {
  EXPECT_THROW(stc::parallelFor(10, 2,
                                [](int item, int) {
                                  if (item == 7) throw std::runtime_error("item 7");
                                }),
               std::runtime_error);
  EXPECT_THROW(stc::parallelRanges(10, 2, [](int, int) { throw stc::InputError("range"); }), stc::InputError);
}

TEST(ParallelFor, RefusesToRunInsideAParallelBody) {
  std::atomic<int> refused{0};
  stc::parallelFor(2, 2, [&](int, int) {
    try {
      stc::parallelFor(2, 2, [](int, int) {});
    } catch (const std::logic_error&) {
      ++refused;
    }
  });
  EXPECT_EQ(refused.load(), 2);
}

TEST(ThreadCount, RefusesZeroAndIsRestoredByItsScope) {
  const int before = stc::threadCount();
  EXPECT_GE(before, 1);
  EXPECT_THROW(stc::setThreadCount(0), stc::InputError);
  {
    const stc::ThreadCountScope scope(3);
    EXPECT_EQ(stc::threadCount(), 3);
  }
  EXPECT_EQ(stc::threadCount(), before);
}

// Two threads inside scopes of their own at the same time (the Python module's threads= on two
// Python threads): each sees its own count, and neither changes the other's nor the process's.
TEST(ThreadCount, AScopeSetsTheCountOfItsOwnThreadOnly) {
  const int process = stc::threadCount();
  std::latch both_scoped(2), both_read(2);
  int seen_one = 0, seen_three = 0;
  const auto scoped = [&](int n, int& seen) {
    const stc::ThreadCountScope scope(n);
    both_scoped.arrive_and_wait();
    seen = stc::threadCount();
    both_read.arrive_and_wait();
  };
  std::thread one([&] { scoped(1, seen_one); });
  std::thread three([&] { scoped(3, seen_three); });
  one.join();
  three.join();
  EXPECT_EQ(seen_one, 1);
  EXPECT_EQ(seen_three, 3);
  EXPECT_EQ(stc::threadCount(), process);
}

TEST(ThreadCount, AScopeIsRefusedAsSetThreadCountIs) {
  const int before = stc::threadCount();
  EXPECT_THROW(stc::ThreadCountScope(0), stc::InputError);
  EXPECT_THROW(stc::ThreadCountScope(stc::maxThreadCount() + 1), stc::InputError);
  EXPECT_EQ(stc::threadCount(), before);
}
