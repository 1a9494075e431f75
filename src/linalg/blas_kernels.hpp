#pragma once
// OpenBLAS chooses its kernels for the processor when it is loaded (its DYNAMIC_ARCH build, which
// Debian ships). Debian 12's OpenBLAS 0.3.21 does not know processors released after it (Intel Xeon
// family 6 model 207, for one) and falls back to its generic "Prescott" kernels (SSE3), whatever
// the processor offers: dense products then run at a fraction of its speed (fas-apriori at 801
// contact nodes: 1.79 s with them, 1.01 s with the SkylakeX kernels on the same machine;
// docs/threads.md, "BLAS kernels"). preferFastBlasKernels() switches OpenBLAS to the kernels the
// processor supports when it fell back, through OpenBLAS's own start-up path (the documented
// variable OPENBLAS_CORETYPE, then its dynamic initialisation again).
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

}  // namespace stc::linalg
