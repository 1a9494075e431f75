// Micro-benchmarks of the pieces of a solve (docs/micro_benchmarks.md, docs/threads.md), each on the seed scene (arc_nodes 101: n = 1088 free
// dofs, n_C = 101, m = 201) and on a finer mesh of it (arc_nodes 401), on 1 and 2 threads where the
// piece is threaded; every row is labelled with its sizes.
//   LocalStage       the contact law on all nodes × instants (docs/method.md §2)
//   GlobalStage      m right-hand sides built, solved with the factor (by blocks of 32 instants),
//                    and the interface quantities v = B u, λ = λ̂ − k (v − v̂)
//   SeparatedStage   the separated global stage (docs/method.md §5) on the directions found by 20
//                    iterations of latin-pgd, without enrichment: three products with p columns
//   LatinIteration   local stage + exact global stage + indicator
//   CoarseStep       one FAS coarse step at the defaults (i_C = 8, Anderson depth 2, on its
//                    contact zone), in the fas-apriori coarse space (default modes + increment
//                    modes, seed eqs. (3)–(8)); CoarseStepEveryNode the same with coarse_zone off
//   CoarseSpace      the fas-apriori coarse space from the separated iterate (energy SVD of the
//                    expansion's factors, pgd/separated_history.hpp)
// Build and run (docs/micro_benchmarks.md):
//   cmake -S . -B build -DSTC_BUILD_BENCHMARKS=ON && cmake --build build --target bench_stages
//   build/bench/bench_stages --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>

#include "stcontact/core/threads.hpp"
#include "stcontact/fas/apriori/apriori_basis.hpp"
#include "stcontact/fas/coarse_step.hpp"
#include "stcontact/latin/global_stage.hpp"
#include "stcontact/latin/indicator.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/pgd/controlled_global_stage.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace {

// The seed scene at `arc_nodes` contact nodes, κ = 3 as bench_latin, after 20 LATIN iterations
// (open, stick and slip nodes); a separated global stage whose directions 20 iterations of
// latin-pgd built, and the fas-apriori coarse space of its iterate.
struct Sized {
  stc::Problem problem;
  stc::latin::GlobalStage global{problem};
  stc::InterfaceHistory s, hat, s_new;
  stc::pgd::ControlledGlobalStage separated{problem, {}};
  stc::fas::AprioriBasisProvider provider{separated, {}};
  stc::fas::CoarseSpace space;

  explicit Sized(int arc_nodes)
      : problem(stc::buildProblem(stc::readScene(STC_SOURCE_DIR "/examples/scenes/hemicylinder.toml",
                                                 {"solver.search_scale=3", "mesh.arc_nodes=" + std::to_string(arc_nodes)}))) {
    s = stc::InterfaceHistory::zeros(problem.contact, problem.numSteps());
    stc::InterfaceHistory sep = s, sep_hat;
    for (int i = 0; i < 20; ++i) {
      step();
      stc::latin::localStage(problem.contact, sep, sep_hat);
      separated.solve(sep_hat, sep);
      double gap = 0.0;
      stc::latin::indicator(problem.contact.search_direction, sep, sep_hat, &gap);
      separated.observeGap(gap);
    }
    space = provider.coarseSpace(sep_hat);
    separated.observeGap(1e300);  // the benchmark measures the products, not enrichment
  }
  double step() {
    stc::latin::localStage(problem.contact, s, hat);
    global.solve(hat, s_new);
    const double eta = stc::latin::indicator(problem.contact.search_direction, s_new, hat);
    std::swap(s, s_new);
    return eta;
  }
};

Sized& sized(int arc_nodes) {
  static std::map<int, std::unique_ptr<Sized>> cache;
  auto& entry = cache[arc_nodes];
  if (!entry) entry = std::make_unique<Sized>(arc_nodes);
  return *entry;
}

// The row's sizes as counters (columns of the table, fields of --benchmark_format=json); r only
// where there is a basis.
void label(benchmark::State& state, const Sized& z, int r = -1) {
  state.counters["n"] = z.problem.numFreeDofs();
  state.counters["n_C"] = z.problem.contact.size();
  state.counters["m"] = z.problem.numSteps();
  if (r >= 0) state.counters["r"] = r;
  state.counters["threads"] = static_cast<double>(state.range(1));
}

void LocalStage(benchmark::State& state) {
  Sized& z = sized(static_cast<int>(state.range(0)));
  const stc::ThreadCountScope threads(static_cast<int>(state.range(1)));
  for (auto _ : state) {
    stc::latin::localStage(z.problem.contact, z.s, z.hat);
    benchmark::ClobberMemory();
  }
  label(state, z);
}

void GlobalStage(benchmark::State& state) {
  Sized& z = sized(static_cast<int>(state.range(0)));
  const stc::ThreadCountScope threads(static_cast<int>(state.range(1)));
  for (auto _ : state) {
    z.global.solve(z.hat, z.s_new);
    benchmark::ClobberMemory();
  }
  label(state, z);
}

void LatinIteration(benchmark::State& state) {
  Sized& z = sized(static_cast<int>(state.range(0)));
  const stc::ThreadCountScope threads(static_cast<int>(state.range(1)));
  for (auto _ : state) benchmark::DoNotOptimize(z.step());
  label(state, z);
}

void coarseStepWith(benchmark::State& state, const stc::fas::FasOptions& options) {
  Sized& z = sized(static_cast<int>(state.range(0)));
  const stc::ThreadCountScope threads(static_cast<int>(state.range(1)));
  stc::InterfaceHistory hat;
  for (auto _ : state) {
    state.PauseTiming();
    stc::latin::localStage(z.problem.contact, z.s, hat);  // the coarse step's input s̃
    state.ResumeTiming();
    stc::fas::coarseStep(z.problem.contact, z.space, options, z.s, hat);
    benchmark::ClobberMemory();
  }
  label(state, z, z.space.rank());
}

void CoarseStep(benchmark::State& state) { coarseStepWith(state, stc::fas::FasOptions{}); }

void CoarseStepEveryNode(benchmark::State& state) {
  stc::fas::FasOptions options;
  options.coarse_zone = false;
  coarseStepWith(state, options);
}

void SeparatedStage(benchmark::State& state) {
  Sized& z = sized(static_cast<int>(state.range(0)));
  const stc::ThreadCountScope threads(static_cast<int>(state.range(1)));
  for (auto _ : state) {
    z.separated.solve(z.hat, z.s_new);
    benchmark::ClobberMemory();
  }
  label(state, z, z.separated.rank());
}

void CoarseSpace(benchmark::State& state) {
  Sized& z = sized(static_cast<int>(state.range(0)));
  const stc::ThreadCountScope threads(static_cast<int>(state.range(1)));
  stc::fas::AprioriBasisProvider provider{z.separated, {}};
  int rank = 0;
  for (auto _ : state) rank = provider.coarseSpace(z.hat).rank();
  label(state, z, rank);
}

// Arguments: {arc_nodes, threads}.
void threaded(benchmark::internal::Benchmark* b) { b->ArgsProduct({{101, 401}, {1, 2}}); }
void serial(benchmark::internal::Benchmark* b) { b->ArgsProduct({{101, 401}, {1}}); }

BENCHMARK(LocalStage)->Apply(threaded)->Unit(benchmark::kMicrosecond);
BENCHMARK(GlobalStage)->Apply(threaded)->Unit(benchmark::kMillisecond);
BENCHMARK(LatinIteration)->Apply(threaded)->Unit(benchmark::kMillisecond);
BENCHMARK(CoarseStep)->Apply(threaded)->Unit(benchmark::kMillisecond);
BENCHMARK(CoarseStepEveryNode)->Apply(threaded)->Unit(benchmark::kMillisecond);
BENCHMARK(SeparatedStage)->Apply(serial)->Unit(benchmark::kMillisecond);
BENCHMARK(CoarseSpace)->Apply(serial)->Unit(benchmark::kMillisecond);

}  // namespace
