// Threads change no arithmetic (src/core/threads.hpp, docs/threads.md): the local stage, the
// global stage and whole LATIN solves give bitwise the same iterates on 1, 2 and 3 threads.
// Exact equality is the claim: each node, each block of instants and each CHOLMOD chunk of 16
// columns is computed by the same code on the same data whichever thread takes it
// (tests/linalg/test_cholmod_factor.cpp: the same columns from any workspace, also concurrently).
#include <gtest/gtest.h>

#include "fixtures/seed_scene.hpp"
#include "stcontact/core/threads.hpp"
#include "stcontact/latin/global_stage.hpp"
#include "stcontact/latin/latin_solver.hpp"
#include "stcontact/latin/local_stage.hpp"

namespace {

const stc::Problem& problem() {
  static const stc::Problem p = [] {
    stc::Scene scene = stc::test::seedScene(31, 41);
    scene.search_direction.scale = 3.0;
    return stc::buildProblem(scene);
  }();
  return p;
}

stc::InterfaceHistory randomState(unsigned seed) {
  std::srand(seed);
  const auto& p = problem();
  stc::InterfaceHistory s{0.01 * Eigen::MatrixXd::Random(2 * p.contact.size(), p.numSteps()),
                          50.0 * Eigen::MatrixXd::Random(2 * p.contact.size(), p.numSteps())};
  return s;
}

bool identical(const stc::InterfaceHistory& a, const stc::InterfaceHistory& b) {
  return a.v.rows() == b.v.rows() && a.v.cols() == b.v.cols() && a.v == b.v && a.lambda == b.lambda;
}

}  // namespace

TEST(LocalStage, ThreadsGiveBitwiseTheSerialResult) {
  const stc::InterfaceHistory s = randomState(3);
  stc::InterfaceHistory serial, threaded;
  {
    const stc::ThreadCountScope one(1);
    stc::latin::localStage(problem().contact, s, serial);
  }
  for (int threads : {2, 3}) {
    const stc::ThreadCountScope scope(threads);
    stc::latin::localStage(problem().contact, s, threaded);
    EXPECT_TRUE(identical(serial, threaded)) << threads << " threads";
  }
}

// The coarse step's form (fas/coarse_step.cpp runs it on threads on large fields).
TEST(LocalStageOfTrial, ThreadsGiveBitwiseTheSerialResult) {
  const stc::InterfaceHistory a = randomState(5), b = randomState(6);
  stc::InterfaceHistory serial, threaded;
  Eigen::MatrixXd serial_image, threaded_image;
  {
    const stc::ThreadCountScope one(1);
    stc::latin::localStageOfTrial(problem().contact, a.v, b.v, a.lambda, &serial, &serial_image);
  }
  for (int threads : {2, 3}) {
    const stc::ThreadCountScope scope(threads);
    stc::latin::localStageOfTrial(problem().contact, a.v, b.v, a.lambda, &threaded, &threaded_image);
    EXPECT_TRUE(identical(serial, threaded)) << threads << " threads";
    EXPECT_TRUE(serial_image == threaded_image) << threads << " threads";
  }
}

TEST(GlobalStage, ThreadsGiveBitwiseTheSerialResult) {
  stc::latin::GlobalStage global(problem(), 7);  // 6 blocks, the last one shorter
  const stc::InterfaceHistory hat = randomState(4);
  stc::InterfaceHistory serial, threaded;
  Eigen::MatrixXd u_serial, u_threaded;
  {
    const stc::ThreadCountScope one(1);
    global.solve(hat, serial, &u_serial);
  }
  for (int threads : {2, 3}) {
    const stc::ThreadCountScope scope(threads);
    global.solve(hat, threaded, &u_threaded);
    EXPECT_TRUE(identical(serial, threaded)) << threads << " threads";
    EXPECT_TRUE(u_serial == u_threaded) << threads << " threads";
  }
}

TEST(LatinSolver, ThreadsGiveBitwiseTheSerialIterates) {
  stc::latin::LatinOptions options;
  options.stop.tolerance = 1e-8;
  auto run = [&](int threads) {
    const stc::ThreadCountScope scope(threads);
    return stc::latin::solveLatin(problem(), options);
  };
  const stc::SolveResult serial = run(1), threaded = run(2);
  ASSERT_TRUE(serial.summary.converged());
  ASSERT_EQ(serial.summary.history.size(), threaded.summary.history.size());
  for (std::size_t i = 0; i < serial.summary.history.size(); ++i)
    EXPECT_EQ(serial.summary.history[i].indicator, threaded.summary.history[i].indicator) << "iteration " << i + 1;
  EXPECT_TRUE(identical(serial.interface, threaded.interface));
}
