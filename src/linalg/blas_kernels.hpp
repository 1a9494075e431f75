#pragma once
// OpenBLAS chooses its kernels for the processor when it is loaded (its DYNAMIC_ARCH build, which
// Debian ships). Debian 12's OpenBLAS 0.3.21 does not know processors released after it (Intel Xeon
// family 6 model 207, for one) and falls back to its generic "Prescott" kernels (SSE3), whatever
// the processor offers: dense products then run at a fraction of its speed (fas-apriori at 801
// contact nodes: 1.79 s with them, 1.01 s with the SkylakeX kernels on the same machine;
// docs/threads.md, "BLAS kernels"). preferFastBlasKernels() switches OpenBLAS to the kernels the
// processor supports when it fell back, through OpenBLAS's own start-up path (the documented
// variable OPENBLAS_CORETYPE, then its dynamic initialisation again).
// blasTakesConcurrentCalls() says whether two threads may call the BLAS at once (OpenBLAS's pthread
// or OpenMP build; not its serial one), and holds OpenBLAS to one thread of its own.
#include <string>

namespace stc::linalg {

/// The kernel set OpenBLAS uses now, as it names it ("Prescott", "SkylakeX", "Zen", "Haswell", …).
std::string blasKernels();

/// What to use instead of `active` on this processor: "SkylakeX" (AVX-512 F, CD, BW, DQ and VL, with
/// the system's support for their registers) or "Haswell" (AVX2 and FMA) when `active` is OpenBLAS's
/// generic fallback "Prescott"; empty when `active` is kept (a kernel set OpenBLAS chose for a
/// processor it knows, or a processor with neither).
std::string fasterBlasKernels(const std::string& active);

/// Switches OpenBLAS to fasterBlasKernels(blasKernels()) unless the environment sets
/// OPENBLAS_CORETYPE (the user's choice stands: OPENBLAS_CORETYPE=Prescott keeps the fallback).
/// Call it at the start of a program, before any thread calls the BLAS; the programs of this project
/// do (the command line, the examples, the micro-benchmarks, the Python module). Returns
/// blasKernels() after.
std::string preferFastBlasKernels();

/// Whether threads may call the BLAS concurrently: true for OpenBLAS's pthread and OpenMP builds
/// (openblas_get_parallel() > 0; Debian's libopenblas0-pthread), false for its serial build, which
/// returns wrong columns under concurrent calls (docs/threads.md, "The sparse factor"). Where true,
/// the first call also holds OpenBLAS to one thread of its own (openblas_set_num_threads(1)): the
/// long products and the supernodal solves are split over stcontact's threads instead
/// (dense_product.hpp, cholmod_factor.cpp), by column ranges that leave every column's arithmetic
/// as in one call, so results stay bitwise those of one thread and the two pools do not contend for
/// the cores. Also called once when the library is loaded.
bool blasTakesConcurrentCalls();

/// For one scope, lets OpenBLAS run each call on `threads` threads of its own, where the BLAS takes
/// concurrent calls (else nothing): for work made of a sequence of dense calls that cannot be split
/// by columns, a sparse factorisation's supernodes (CHOLMOD's numeric factorisation: 1.2 to 1.7
/// times faster on two threads at 101k dofs, docs/threads.md). The count is OpenBLAS's, process-wide:
/// while a scope is open, the BLAS calls of other threads may run on OpenBLAS's threads too (their
/// last bits then those of a threaded call). Back to one thread when the last open scope closes.
class BlasThreadsScope {
 public:
  explicit BlasThreadsScope(int threads);
  ~BlasThreadsScope();
  BlasThreadsScope(const BlasThreadsScope&) = delete;
  BlasThreadsScope& operator=(const BlasThreadsScope&) = delete;

 private:
  bool opened_ = false;
};

}  // namespace stc::linalg
