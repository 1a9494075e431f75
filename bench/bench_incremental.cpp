// Wall time of the incremental reference solver (src/incremental/incremental_solver.hpp) on the seed
// scene (arc_nodes 101, steps 201), with the set-up (factorisation, W, v_0 and instant 0) and the
// Newton iterations as counters.
//   cmake -B build -DSTC_BUILD_BENCHMARKS=ON && cmake --build build --target bench_incremental
//   build/bench/bench_incremental --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <regex>
#include <string>

#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace {

int newtonIterations(const std::string& message) {
  std::smatch match;
  if (!std::regex_search(message, match, std::regex("([0-9]+) Newton iterations"))) return -1;
  return std::stoi(match[1]);
}

void IncrementalSeedScene(benchmark::State& state) {
  const stc::Problem problem =
      stc::buildProblem(stc::readScene(STC_SOURCE_DIR "/examples/scenes/hemicylinder.toml"));
  stc::SolveSummary summary;
  for (auto _ : state) {
    summary = stc::solveIncremental(problem).summary;
    if (!summary.converged()) state.SkipWithError(summary.message.c_str());
  }
  state.counters["setup_ms"] = summary.history.empty() ? 0.0 : summary.history.front().wall_s * 1e3;
  state.counters["newton_iterations"] = newtonIterations(summary.message);
}
BENCHMARK(IncrementalSeedScene)->Unit(benchmark::kMillisecond);

}  // namespace
