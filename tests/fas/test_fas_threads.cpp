// Threads change no arithmetic (docs/threads.md): `fas-apriori` and `latin-pgd` (local stages in
// the coarse step and the PGD loop, global stages, enrichment) give bitwise the same history and
// solution on 1 and 2 threads.
#include <gtest/gtest.h>

#include "fixtures/seed_scene.hpp"
#include "stcontact/core/threads.hpp"
#include "stcontact/strategies/registry.hpp"

namespace {

stc::SolveResult solveOn(int threads, const std::string& name, const stc::Problem& problem, const stc::Scene& scene) {
  const stc::ThreadCountScope scope(threads);
  stc::SolverSpec spec = scene.solver;
  spec.setTolerance(1e-8);
  return stc::solve(stc::strategyNamed(name), problem, spec);
}

}  // namespace

TEST(SolveByName, ThreadsGiveBitwiseTheSerialIteratesOfFasAprioriAndLatinPgd) {
  const stc::Scene scene = stc::test::seedScene(31, 41);
  const stc::Problem problem = stc::buildProblem(scene);
  for (const std::string name : {"fas-apriori", "latin-pgd"}) {
    const stc::SolveResult serial = solveOn(1, name, problem, scene), threaded = solveOn(2, name, problem, scene);
    ASSERT_TRUE(serial.summary.converged()) << name;
    ASSERT_EQ(serial.summary.history.size(), threaded.summary.history.size()) << name;
    for (std::size_t i = 0; i < serial.summary.history.size(); ++i) {
      EXPECT_EQ(serial.summary.history[i].indicator, threaded.summary.history[i].indicator) << name << " " << i;
      EXPECT_EQ(serial.summary.history[i].rank, threaded.summary.history[i].rank) << name << " " << i;
    }
    EXPECT_TRUE(serial.interface.v == threaded.interface.v) << name;
    EXPECT_TRUE(serial.interface.lambda == threaded.interface.lambda) << name;
  }
}
