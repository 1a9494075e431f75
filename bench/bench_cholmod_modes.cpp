// Why CholmodFactor is a simplicial CHOLMOD factor (src/linalg/spd_factor.cpp, docs/threads.md):
//   Solve/<mode>/<arc_nodes>         201 right-hand sides of the global-stage operator K + BᵀkB in
//                                    chunks of 16, supernodal (mode 0, the BLAS) or simplicial LLᵀ
//                                    (mode 1, plain C); the CPU time column is this thread's
//   ConcurrentSolve/<mode>/<arc_nodes>  two threads solving a 16-column chunk 20 times each, at
//                                    once, each with its own cholmod_common and workspaces, one
//                                    factor; wrong_percent = solves whose result differs from the
//                                    serial one (Debian's serial OpenBLAS is not safe for
//                                    concurrent calls: the supernodal rows are not 0)
//   Solve3d/<mode>/<divisions>/<chunk>  288 right-hand sides of the half-ball's K + BᵀkB (3D) in
//                                    chunks of <chunk>, one thread: why CholmodFactor keeps a 3D factor
//                                    supernodal and solves it on one thread (src/linalg/spd_factor.cpp)
//   cmake --build build --target bench_cholmod_modes && build/bench/bench_cholmod_modes
#include <benchmark/benchmark.h>

#include <Eigen/CholmodSupport>
#include <thread>

#include "stcontact/latin/global_stage.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace {

struct Factor {
  cholmod_common common;
  cholmod_factor* L = nullptr;
  Factor(const Eigen::SparseMatrix<double>& A, bool supernodal) {
    cholmod_start(&common);
    common.supernodal = supernodal ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
    common.final_asis = supernodal ? 1 : 0;  // as Eigen's CholmodSupernodalLLT / CholmodSimplicialLLT
    common.final_ll = 1;
    cholmod_sparse view = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
    L = cholmod_analyze(&view, &common);
    double beta[2] = {0.0, 0.0};
    cholmod_factorize_p(&view, beta, nullptr, 0, L, &common);
  }
  ~Factor() {
    cholmod_free_factor(&L, &common);
    cholmod_finish(&common);
  }
};

// X = A⁻¹ B by chunks of `chunk` columns with the caller's cholmod_common and buffers.
struct Solver {
  cholmod_common common;
  cholmod_dense *X = nullptr, *Y = nullptr, *E = nullptr;
  Solver() { cholmod_start(&common); }
  ~Solver() {
    cholmod_free_dense(&X, &common);
    cholmod_free_dense(&Y, &common);
    cholmod_free_dense(&E, &common);
    cholmod_finish(&common);
  }
  Eigen::MatrixXd solve(cholmod_factor* L, const Eigen::MatrixXd& B, Eigen::Index chunk = 16) {
    Eigen::MatrixXd out(B.rows(), B.cols());
    for (Eigen::Index c = 0; c < B.cols(); c += chunk) {
      const Eigen::Index cols = std::min<Eigen::Index>(chunk, B.cols() - c);
      cholmod_dense b{};
      b.nrow = B.rows();
      b.ncol = cols;
      b.nzmax = B.rows() * cols;
      b.d = B.rows();
      b.x = const_cast<double*>(B.data() + c * B.rows());
      b.xtype = CHOLMOD_REAL;
      b.dtype = CHOLMOD_DOUBLE;
      cholmod_solve2(CHOLMOD_A, L, &b, nullptr, &X, nullptr, &Y, &E, &common);
      out.middleCols(c, cols) = Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(X->x), B.rows(), cols);
    }
    return out;
  }
};

Eigen::SparseMatrix<double> globalOperator(int arc_nodes) {
  const stc::Problem problem = stc::buildProblem(stc::readScene(
      STC_SOURCE_DIR "/examples/scenes/hemicylinder.toml", {"solver.search_scale=3", "mesh.arc_nodes=" + std::to_string(arc_nodes)}));
  return stc::searchDirectionOperator(problem);
}

Eigen::SparseMatrix<double> halfBallOperator(int divisions) {
  const stc::Problem problem = stc::buildProblem(
      stc::readScene(STC_SOURCE_DIR "/examples/scenes/hemisphere.toml", {"mesh.divisions=" + std::to_string(divisions)}));
  return stc::searchDirectionOperator(problem);
}

void Solve3d(benchmark::State& state) {
  const Eigen::SparseMatrix<double> A = halfBallOperator(static_cast<int>(state.range(1)));
  const Factor factor(A, state.range(0) == 0);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), 288);
  Solver solver;
  for (auto _ : state) benchmark::DoNotOptimize(solver.solve(factor.L, B, state.range(2)));
  state.SetLabel(state.range(0) == 0 ? "supernodal" : "simplicial");
  state.counters["n"] = static_cast<double>(A.rows());
  state.counters["per_column"] = benchmark::Counter(288, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void Solve(benchmark::State& state) {
  const Eigen::SparseMatrix<double> A = globalOperator(static_cast<int>(state.range(1)));
  const Factor factor(A, state.range(0) == 0);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), 201);
  Solver solver;
  for (auto _ : state) benchmark::DoNotOptimize(solver.solve(factor.L, B));
  state.SetLabel(state.range(0) == 0 ? "supernodal" : "simplicial");
  state.counters["n"] = static_cast<double>(A.rows());
}

void ConcurrentSolve(benchmark::State& state) {
  const Eigen::SparseMatrix<double> A = globalOperator(static_cast<int>(state.range(1)));
  const Factor factor(A, state.range(0) == 0);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), 16);
  Solver serial, first, second;
  const Eigen::MatrixXd X = serial.solve(factor.L, B);
  long wrong = 0, total = 0;
  for (auto _ : state) {  // each thread solves 20 times in a row, so that the solves overlap
    int a_wrong = 0, b_wrong = 0;
    std::thread a([&] { for (int r = 0; r < 20; ++r) a_wrong += !(first.solve(factor.L, B) == X); });
    std::thread b([&] { for (int r = 0; r < 20; ++r) b_wrong += !(second.solve(factor.L, B) == X); });
    a.join();
    b.join();
    wrong += a_wrong + b_wrong;
    total += 40;
  }
  state.SetLabel(state.range(0) == 0 ? "supernodal" : "simplicial");
  state.counters["n"] = static_cast<double>(A.rows());
  state.counters["wrong_percent"] = 100.0 * static_cast<double>(wrong) / static_cast<double>(total);
}

BENCHMARK(Solve)->ArgsProduct({{0, 1}, {101, 201, 401}})->Unit(benchmark::kMillisecond);
BENCHMARK(Solve3d)->ArgsProduct({{0, 1}, {8, 12}, {4, 16, 32}})->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(ConcurrentSolve)->ArgsProduct({{0, 1}, {101}})->Iterations(200)->Unit(benchmark::kMillisecond);

}  // namespace
