#pragma once
// How much memory a run may use: the machine's available memory and the process's address-space
// limit (`ulimit -v`). A run whose estimated need exceeds it is refused before anything is written
// (src/problem/size_estimate.hpp), and a limit too low for any run is refused at once: under
// `ulimit -v` of 100-200 MB, Debian 12's OpenBLAS 0.3.21 spins forever in its buffer allocator when a
// mapping fails (github.com/OpenMathLib/OpenBLAS/issues/5289, fixed after that version).
#include <string>

namespace stc {

/// The least address space any run needs: OpenBLAS's buffers, one malloc arena and one stack per
/// thread, the libraries mapped. The seed scene solves in 300 MB and spins in 200 MB; 512 MiB leaves
/// a margin.
inline constexpr double kMinAddressSpaceBytes = 512.0 * 1024 * 1024;

/// The soft RLIMIT_AS in bytes, +∞ when unlimited.
double addressSpaceLimitBytes();

/// Bytes this process may still allocate: the smaller of the machine's available memory
/// (MemAvailable of /proc/meminfo, +∞ when unknown) and the address-space limit less the process's
/// current size (/proc/self/statm).
double availableMemoryBytes();

/// The process's peak resident size since it started, in bytes (getrusage's ru_maxrss): what a
/// run needed of the machine's memory so far, 0 where unknown.
double peakResidentBytes();

/// Throws InputError when the address-space limit is below kMinAddressSpaceBytes.
void requireUsableAddressSpace();

/// "1.5 GB", "320 MB": bytes for messages.
std::string bytesText(double bytes);

}  // namespace stc
