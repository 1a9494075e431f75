#pragma once
// Peak resident memory of this process over a stretch of work (docs/compare.md, "Memory").
//
// Method (Linux ≥ 4.0): reset() first gives freed heap back to the system (malloc_trim), then writes
// "5" to /proc/self/clear_refs, which sets the kernel's resident high-water mark (VmHWM of
// /proc/self/status) to the current resident size (VmRSS), and records that size as the baseline.
// sample() then reads VmHWM: the largest resident size since the reset. Its growth over the
// baseline is what the work needed beyond what the process already held (the problem, the
// reference solution). Freed heap that malloc_trim cannot release (fragmentation) may be reused
// without raising the mark, so the growth is a lower bound of the work's own peak.
// Where the reset is refused, the peak is getrusage's ru_maxrss: the process's peak since it
// started, not the stretch's; resettable() says which one was measured.
#include <string>

namespace stc {

struct MemoryUse {
  double baseline_mb = 0.0;  ///< resident size at the reset
  double peak_mb = 0.0;      ///< largest resident size since the reset (or since the start)
  bool since_reset = false;  ///< false: process peak since its start (reset refused)

  double growthMb() const { return peak_mb > baseline_mb ? peak_mb - baseline_mb : 0.0; }
};

class PeakMemoryProbe {
 public:
  /// Releases freed heap, resets the high-water mark, records the baseline.
  void reset();
  MemoryUse sample() const;
  bool resettable() const { return resettable_; }

 private:
  double baseline_mb_ = 0.0;
  bool resettable_ = false;
};

/// One sentence saying how MemoryUse was measured (since_reset or not), for the report.
std::string describeMemoryMethod(bool since_reset);

/// Current VmRSS and VmHWM of this process in MB (0 where /proc is missing).
double residentMb();
double residentPeakMb();

}  // namespace stc
