#include "stcontact/studies/peak_memory.hpp"

#include <malloc.h>

#include <fstream>
#include <sstream>

#include "stcontact/core/memory.hpp"

namespace stc {
namespace {

constexpr double kResetSlackMb = 1.0;  // the resident size may move a little between two reads

/// The value in kB of a "Name:   1234 kB" line of /proc/self/status, in MB; 0 if absent.
double statusFieldMb(const std::string& name) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(name + ":", 0) != 0) continue;
    std::istringstream fields(line.substr(name.size() + 1));
    double kb = 0.0;
    fields >> kb;
    return kb / 1024.0;
  }
  return 0.0;
}

bool resetHighWaterMark() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return static_cast<bool>(clear);
}

double processPeakSinceStartMb() { return peakResidentBytes() / (1024.0 * 1024.0); }

}  // namespace

double residentMb() { return statusFieldMb("VmRSS"); }
double residentPeakMb() { return statusFieldMb("VmHWM"); }

void PeakMemoryProbe::reset() {
  malloc_trim(0);
  const bool written = resetHighWaterMark();
  baseline_mb_ = residentMb();
  // A kernel that accepts the write but ignores "5" leaves an older, higher mark: check it moved.
  resettable_ = written && residentPeakMb() <= baseline_mb_ + kResetSlackMb;
}

MemoryUse PeakMemoryProbe::sample() const {
  MemoryUse use;
  use.baseline_mb = baseline_mb_;
  use.since_reset = resettable_;
  use.peak_mb = resettable_ ? residentPeakMb() : processPeakSinceStartMb();
  return use;
}

std::string describeMemoryMethod(bool since_reset) {
  if (since_reset)
    return "before each strategy, freed heap is returned to the system (malloc_trim) and the kernel's "
           "resident high-water mark is reset (echo 5 > /proc/self/clear_refs); the peak is VmHWM of "
           "/proc/self/status after the strategy's runs, the growth is that peak minus the resident size "
           "at the reset (the problem and the reference solution, held throughout, are in the baseline)";
  return "the kernel refused to reset the resident high-water mark (/proc/self/clear_refs): the peak is "
         "getrusage's ru_maxrss, the process's peak since it started, so it is not per strategy";
}

}  // namespace stc
