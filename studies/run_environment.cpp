#include "stcontact/studies/run_environment.hpp"

#include <sched.h>
#include <sys/utsname.h>

#include <fstream>
#include <sstream>
#include <thread>

#include "stc_git_commit.hpp"  // STC_GIT_COMMIT, generated at build time
#include "stcontact/core/threads.hpp"
#include "stcontact/linalg/blas_kernels.hpp"

namespace stc {
namespace {

std::string cpuModel() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos) break;
    const auto start = line.find_first_not_of(" \t", colon + 1);
    return start == std::string::npos ? "unknown" : line.substr(start);
  }
  return "unknown";
}

int usableCores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 0;
  return CPU_COUNT(&set);
}

std::string kernel() {
  utsname name{};
  if (uname(&name) != 0) return "unknown";
  return std::string(name.sysname) + " " + name.release;
}

std::string orUnknown(std::string text) { return text.empty() ? "unknown" : text; }

}  // namespace

std::string loadAverage() {
  std::ifstream file("/proc/loadavg");
  std::string one, five, fifteen;
  if (!(file >> one >> five >> fifteen)) return "";
  return one + " " + five + " " + fifteen;
}

RunEnvironment describeRunEnvironment() {
  RunEnvironment env;
  env.cpu_model = cpuModel();
  env.logical_cores = static_cast<int>(std::thread::hardware_concurrency());
  env.usable_cores = usableCores();
  env.kernel = kernel();
#if defined(__clang__)
  env.compiler = __VERSION__;  // "Clang 15.0.6 ..." already names the compiler
#elif defined(__GNUC__)
  env.compiler = "GCC " __VERSION__;
#endif
  env.build_type = orUnknown(STC_BUILD_TYPE);
  env.git_commit = orUnknown(STC_GIT_COMMIT);
  env.load_average = loadAverage();
  env.threads = threadCount();
  env.blas_kernels = orUnknown(linalg::blasKernels());
  return env;
}

std::string machineMarkdown(const RunEnvironment& e, const std::string& load_after) {
  std::ostringstream out;
  out << "## Machine and build\n\n"
      << "- CPU: " << e.cpu_model << "; " << e.logical_cores << " logical cores, " << e.usable_cores
      << " usable by this process; stcontact threads: " << e.threads << "; OpenBLAS kernels: "
      << e.blas_kernels << "\n"
      << "- kernel: " << e.kernel << "\n- compiler: " << e.compiler << "; build type " << e.build_type
      << "; commit " << e.git_commit << "\n"
      << "- load average (1, 5, 15 min) at the start: " << (e.load_average.empty() ? "unknown" : e.load_average)
      << "; at the end: " << (load_after.empty() ? "unknown" : load_after) << "\n";
  return out.str();
}

}  // namespace stc
