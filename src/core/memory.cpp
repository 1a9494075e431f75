#include "stcontact/core/memory.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

#include "stcontact/core/input_error.hpp"

namespace stc {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// MemAvailable of /proc/meminfo in bytes, +∞ when unknown.
double machineAvailableBytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kilobytes = 0.0;
  std::string unit;
  while (meminfo >> key >> kilobytes >> unit)
    if (key == "MemAvailable:") return kilobytes * 1024.0;
  return kInfinity;
}

/// The process's current virtual size in bytes (/proc/self/statm, pages), 0 when unknown.
double processSizeBytes() {
  std::ifstream statm("/proc/self/statm");
  double pages = 0.0;
  statm >> pages;
  return pages * static_cast<double>(sysconf(_SC_PAGESIZE));
}

}  // namespace

double addressSpaceLimitBytes() {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kInfinity;
  return static_cast<double>(limit.rlim_cur);
}

double availableMemoryBytes() {
  const double limit = addressSpaceLimitBytes();
  const double left = std::isfinite(limit) ? std::max(0.0, limit - processSizeBytes()) : kInfinity;
  return std::min(machineAvailableBytes(), left);
}

double peakResidentBytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0.0;
  return static_cast<double>(usage.ru_maxrss) * 1024.0;  // ru_maxrss is in kB on Linux
}

void requireUsableAddressSpace() {
  const double limit = addressSpaceLimitBytes();
  if (limit >= kMinAddressSpaceBytes) return;
  throw InputError("the address-space limit (ulimit -v) is " + bytesText(limit) + ", below the " +
                   bytesText(kMinAddressSpaceBytes) +
                   " any run needs (OpenBLAS's buffers, a malloc arena and a stack per thread): raise it");
}

std::string bytesText(double bytes) {
  char text[48];
  if (!std::isfinite(bytes)) return "unlimited";
  if (bytes >= 1e9) std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
  else std::snprintf(text, sizeof text, "%.3g MB", bytes / 1e6);
  return text;
}

}  // namespace stc
