#include "stcontact/linalg/blas_kernels.hpp"

#include <cstdlib>

// OpenBLAS's own entry points (exported by libopenblas.so.0 of its DYNAMIC_ARCH build): the name of
// the kernel set in use, and the start-up and shut-down of its kernel choice
// (driver/others/dynamic.c, which reads OPENBLAS_CORETYPE at initialisation).
extern "C" {
char* openblas_get_corename(void);
void gotoblas_dynamic_init(void);
void gotoblas_dynamic_quit(void);
}

namespace stc::linalg {
namespace {

bool supportsAvx512() {
#if defined(__x86_64__) && defined(__GNUC__)
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
         __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
         __builtin_cpu_supports("avx512vl");
#else
  return false;
#endif
}

bool supportsAvx2() {
#if defined(__x86_64__) && defined(__GNUC__)
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

}  // namespace

std::string blasKernels() {
  const char* name = openblas_get_corename();
  return name ? name : "";
}

std::string fasterBlasKernels(const std::string& active) {
  if (active != "Prescott") return "";
  if (supportsAvx512()) return "SkylakeX";
  if (supportsAvx2()) return "Haswell";
  return "";
}

std::string preferFastBlasKernels() {
  if (std::getenv("OPENBLAS_CORETYPE") != nullptr) return blasKernels();
  const std::string faster = fasterBlasKernels(blasKernels());
  if (faster.empty()) return blasKernels();
  // Set, not only for this process: a program it starts with the same OpenBLAS makes the same
  // choice.
  setenv("OPENBLAS_CORETYPE", faster.c_str(), 1);
  gotoblas_dynamic_quit();
  gotoblas_dynamic_init();
  return blasKernels();
}

}  // namespace stc::linalg
