// Cost of one LATIN iteration against the bare multi-right-hand-side CHOLMOD solve it contains
// (docs/latin_iteration_cost.md measures the overhead over that solve), on the seed
// scene (1088 free dofs, 101 contact nodes, 201 instants), κ = 3, on one thread (threads: bench_stages).
//   cmake -B build -DSTC_BUILD_BENCHMARKS=ON && cmake --build build --target bench_latin
//   build/bench/bench_latin --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include "stcontact/core/threads.hpp"
#include "stcontact/latin/global_stage.hpp"
#include "stcontact/latin/indicator.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace {

const stc::Problem& seedProblem() {
  stc::setThreadCount(1);
  static const stc::Problem problem =
      stc::buildProblem(stc::readScene(STC_SOURCE_DIR "/examples/scenes/hemicylinder.toml", {"solver.search_scale=3"}));
  return problem;
}

constexpr int kBlock = stc::defaults::block_size;  // LatinOptions::block_size default

// A state after a few iterations, so that the local stage sees open, stick and slip nodes.
struct Iterate {
  stc::latin::GlobalStage global{seedProblem(), kBlock};
  stc::InterfaceHistory s = stc::InterfaceHistory::zeros(seedProblem().contact, seedProblem().numSteps());
  stc::InterfaceHistory hat, s_new;
  Iterate() {
    for (int i = 0; i < 20; ++i) step();
  }
  double step() {
    stc::latin::localStage(seedProblem().contact, s, hat);
    global.solve(hat, s_new);
    const double eta = stc::latin::indicator(seedProblem().contact.search_direction, s_new, hat);
    std::swap(s, s_new);
    return eta;
  }
};

// The solve alone: (K + BᵀkB)⁻¹ on n_free × m right-hand sides, by the same blocks of instants.
void BareMultiRhsSolve(benchmark::State& state) {
  const stc::Problem& p = seedProblem();
  const stc::latin::GlobalStage global(p, kBlock);
  const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(p.numFreeDofs(), p.numSteps());
  for (auto _ : state)
    for (int k0 = 0; k0 < p.numSteps(); k0 += kBlock) {
      const int count = std::min(kBlock, p.numSteps() - k0);
      benchmark::DoNotOptimize(global.factor().solve(Eigen::MatrixXd(rhs.middleCols(k0, count))));
    }
}
BENCHMARK(BareMultiRhsSolve)->Unit(benchmark::kMillisecond);

void LatinIteration(benchmark::State& state) {
  Iterate it;
  for (auto _ : state) benchmark::DoNotOptimize(it.step());
}
BENCHMARK(LatinIteration)->Unit(benchmark::kMillisecond);

void LocalStage(benchmark::State& state) {
  Iterate it;
  for (auto _ : state) {
    stc::latin::localStage(seedProblem().contact, it.s, it.hat);
    benchmark::ClobberMemory();
  }
}
BENCHMARK(LocalStage)->Unit(benchmark::kMicrosecond);

void GlobalStage(benchmark::State& state) {
  Iterate it;
  for (auto _ : state) {
    it.global.solve(it.hat, it.s_new);
    benchmark::ClobberMemory();
  }
}
BENCHMARK(GlobalStage)->Unit(benchmark::kMillisecond);

void Indicator(benchmark::State& state) {
  Iterate it;
  for (auto _ : state)
    benchmark::DoNotOptimize(stc::latin::indicator(seedProblem().contact.search_direction, it.s, it.hat));
}
BENCHMARK(Indicator)->Unit(benchmark::kMicrosecond);

}  // namespace
