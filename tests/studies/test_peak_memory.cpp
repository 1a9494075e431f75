// The peak-memory probe: after a reset, the peak follows the work done since, not the process's past.
#include "stcontact/studies/peak_memory.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

namespace stc {
namespace {

constexpr std::size_t kBlockBytes = 64u << 20;  // 64 MB, far above the resident size's noise
constexpr double kBlockMb = 64.0;

/// Allocates and touches a block (so it becomes resident), then frees it. The empty asm with a
/// memory clobber makes the writes observable, so the compiler cannot drop the allocation.
void touchBlock() {
  auto block = std::make_unique<char[]>(kBlockBytes);
  std::memset(block.get(), 1, kBlockBytes);
  asm volatile("" : : "r"(block.get()) : "memory");
}

TEST(PeakMemoryProbe, SeesAllocationsMadeAfterTheReset) {
  PeakMemoryProbe probe;
  probe.reset();
  touchBlock();
  const MemoryUse use = probe.sample();
  EXPECT_GE(use.growthMb(), 0.9 * kBlockMb);
  EXPECT_GE(use.peak_mb, use.baseline_mb);
}

TEST(PeakMemoryProbe, ForgetsAPeakReachedBeforeTheReset) {
  touchBlock();  // a peak of at least 64 MB above what follows
  PeakMemoryProbe probe;
  probe.reset();
  if (!probe.resettable()) GTEST_SKIP() << "the kernel refuses to reset the high-water mark (/proc/self/clear_refs)";
  const MemoryUse use = probe.sample();
  EXPECT_TRUE(use.since_reset);
  EXPECT_LT(use.growthMb(), 0.5 * kBlockMb);
}

TEST(PeakMemoryProbe, DescribesTheMethodItUsed) {
  EXPECT_NE(describeMemoryMethod(true).find("clear_refs"), std::string::npos);
  EXPECT_NE(describeMemoryMethod(false).find("ru_maxrss"), std::string::npos);
}

}  // namespace
}  // namespace stc
