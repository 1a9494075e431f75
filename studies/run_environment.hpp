#pragma once
// The machine and build a measurement ran on, for reports that quote times (house style 10).
#include <string>

namespace stc {

struct RunEnvironment {
  std::string cpu_model = "unknown";   ///< "model name" of /proc/cpuinfo
  int logical_cores = 0;               ///< std::thread::hardware_concurrency
  int usable_cores = 0;                ///< cores this process may run on (sched_getaffinity)
  std::string kernel = "unknown";      ///< uname -sr
  std::string compiler = "unknown";    ///< __VERSION__ of the compiler that built the library
  std::string build_type = "unknown";  ///< CMAKE_BUILD_TYPE of the program
  std::string git_commit = "unknown";  ///< commit of the sources at configure time
  std::string load_average;            ///< /proc/loadavg's 1, 5, 15 min averages (shared machines)
  int threads = 1;                     ///< stc::threadCount() when described (docs/threads.md)
  std::string blas_kernels = "unknown";  ///< OpenBLAS's kernel set (src/linalg/blas_kernels.hpp)
};

/// Reads the machine's description and this build's (its type, and the sources' commit recorded at
/// build time).
RunEnvironment describeRunEnvironment();

/// The "## Machine and build" section of a report: CPU, cores, kernel, compiler, build, commit and
/// the load averages at the start (`e.load_average`) and at the end (`load_after`) of the runs.
std::string machineMarkdown(const RunEnvironment& e, const std::string& load_after);

/// The current 1, 5 and 15 minute load averages ("1.02 0.80 0.51"), empty if unknown.
std::string loadAverage();

}  // namespace stc
