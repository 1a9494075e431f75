#include "stcontact/linalg/blas_kernels.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>

// OpenBLAS's own entry points (exported by libopenblas.so.0 of its DYNAMIC_ARCH build): the name of
// the kernel set in use, and the start-up and shut-down of its kernel choice
// (driver/others/dynamic.c, which reads OPENBLAS_CORETYPE at initialisation).
extern "C" {
char* openblas_get_corename(void);
void gotoblas_dynamic_init(void);
void gotoblas_dynamic_quit(void);
int openblas_get_parallel(void);  // 0 serial build, 1 pthreads, 2 OpenMP
void openblas_set_num_threads(int);
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

// OpenBLAS's pthread build starts its threads when it is loaded, before any program could block the
// signals it waits for (src/core/interruption.cpp: SIGTERM and SIGINT, blocked in every thread but
// one that sigwaits): a signal the kernel handed to one of them would end the process at once.
// They are stopped here, once held to one thread (a later count above one starts them again, from
// the thread that asks, with its signal mask). blas_thread_shutdown_ is the pthread build's own
// (its fork handler calls it), looked up so that the serial build, which lacks it, loads too.
void stopOpenBlasThreads() {
  using Shutdown = int (*)();
  if (auto shutdown = reinterpret_cast<Shutdown>(dlsym(RTLD_DEFAULT, "blas_thread_shutdown_"))) shutdown();
}

// Held to one thread as soon as the library is loaded, before any caller's first product.
const bool kConcurrentAtLoad = blasTakesConcurrentCalls();

}  // namespace

bool blasTakesConcurrentCalls() {
  static const bool concurrent = [] {
    if (openblas_get_parallel() == 0) return false;
    openblas_set_num_threads(1);
    stopOpenBlasThreads();
    return true;
  }();
  return concurrent;
}

namespace {
std::mutex scopes_mutex;
int open_scopes = 0;  // BlasThreadsScopes open now, under scopes_mutex
}  // namespace

BlasThreadsScope::BlasThreadsScope(int threads) {
  if (threads < 2 || !blasTakesConcurrentCalls()) return;
  const std::lock_guard lock(scopes_mutex);
  if (open_scopes++ == 0) openblas_set_num_threads(threads);
  opened_ = true;
}

BlasThreadsScope::~BlasThreadsScope() {
  if (!opened_) return;
  const std::lock_guard lock(scopes_mutex);
  if (--open_scopes == 0) openblas_set_num_threads(1);
}

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
