// The main of every micro-benchmark: OpenBLAS's kernels for this processor, as the command line
// takes them (src/linalg/blas_kernels.hpp), then Google Benchmark's own main.
#include <benchmark/benchmark.h>

#include "stcontact/linalg/blas_kernels.hpp"

int main(int argc, char** argv) {
  stc::linalg::preferFastBlasKernels();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
