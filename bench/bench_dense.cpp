// The range finders' dense decompositions (src/linalg/dense_decompositions.hpp) on the shapes a
// solve gives them: orthonormal columns of a sketch of the interface history (rows = the zone's
// interface rows, 201 on the seed scene to 987 at 1601 arc nodes; columns = samples), and the SVD of
// the small projected history (samples × instants). Each against what it replaced: Eigen's
// HouseholderQR with its explicit Q, and Eigen's JacobiSVD.
//   cmake -S . -B build -DSTC_BUILD_BENCHMARKS=ON && cmake --build build --target bench_dense
//   build/bench/bench_dense --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <Eigen/QR>

#include "stcontact/linalg/dense_decompositions.hpp"

namespace {

using stc::linalg::gaussianSketch;

void shapesOfSketches(benchmark::internal::Benchmark* b) {
  for (const int rows : {201, 462, 987})
    for (const int cols : {20, 55, 100}) b->Args({rows, cols});
}

void shapesOfProjections(benchmark::internal::Benchmark* b) {
  for (const int rows : {25, 40, 55, 64})
    for (const int instants : {201, 2001}) b->Args({rows, instants});
}

void OrthonormalColumns(benchmark::State& state) {
  const Eigen::MatrixXd Y = gaussianSketch(state.range(0), state.range(1), 1);
  for (auto _ : state) benchmark::DoNotOptimize(stc::linalg::orthonormalColumns(Y).data());
}

void EigenHouseholderQ(benchmark::State& state) {
  const Eigen::MatrixXd Y = gaussianSketch(state.range(0), state.range(1), 1);
  for (auto _ : state) {
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(Y);
    const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(Y.rows(), Y.cols());
    benchmark::DoNotOptimize(Q.data());
  }
}

void ProjectedSvd(benchmark::State& state, stc::linalg::SvdMethod method) {
  const Eigen::MatrixXd M = gaussianSketch(state.range(0), state.range(1), 2);
  for (auto _ : state) {
    const stc::linalg::Svd svd = stc::linalg::singularValueDecomposition(M, method, stc::linalg::kThinU);
    benchmark::DoNotOptimize(svd.U.data());
  }
}

}  // namespace

BENCHMARK(OrthonormalColumns)->Apply(shapesOfSketches)->Unit(benchmark::kMicrosecond);
BENCHMARK(EigenHouseholderQ)->Apply(shapesOfSketches)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(ProjectedSvd, qr_iteration, stc::linalg::SvdMethod::qr_iteration)
    ->Apply(shapesOfProjections)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(ProjectedSvd, jacobi, stc::linalg::SvdMethod::jacobi)
    ->Apply(shapesOfProjections)
    ->Unit(benchmark::kMicrosecond);
