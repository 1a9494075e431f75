// FAS's relaxation count under mesh refinement, as MFEM tests convergence orders: `fas-apriori` on
// the seed scene (examples/scenes/hemicylinder.toml) at arc_nodes 51, 101 and 201, with 51 instants
// to keep it short (about 3 s in Release). Relaxations to the tolerance 1e-6 on the error estimate,
// measured (deterministic) with
//   stcontact solve examples/scenes/hemicylinder.toml --solver S --set mesh.arc_nodes=N
//     --set time.steps=51 --no-reference --set output.vtu=false      ("relaxations" in summary.json)
//   arc_nodes         51   101   201   401
//   latin             89   103   193   359
//   fas-apriori       18    21    28    44
// The count grows by 10 from 51 to 201 nodes where LATIN's grows by 104; the test asserts finest <=
// coarsest + 12, the measured growth and 2 for rounding differences between platforms.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "src/problem/problem.hpp"
#include "src/scene/scene_reader.hpp"
#include "src/strategies/solve_by_name.hpp"

namespace {

int relaxationsToTolerance(int arc_nodes) {
  const stc::Scene scene =
      stc::readScene(STC_SOURCE_DIR "/examples/scenes/hemicylinder.toml",
                     {"mesh.arc_nodes=" + std::to_string(arc_nodes), "time.steps=51"});
  const stc::Problem problem = stc::buildProblem(scene);
  const stc::SolveResult result = stc::solveByName("fas-apriori", problem, scene.solver);
  EXPECT_TRUE(result.summary.converged()) << arc_nodes << ": " << result.summary.message;
  return result.summary.relaxations;
}

TEST(FasMeshRefinement, RelaxationsAtArcNodes201StayWithinAMarginOf51) {
  constexpr int kMargin = 12;  // measured growth 28 − 18 = 10, and 2 for platform rounding
  std::vector<int> counts;
  for (int arc_nodes : {51, 101, 201}) counts.push_back(relaxationsToTolerance(arc_nodes));
  EXPECT_LE(counts.back(), counts.front() + kMargin)
      << "relaxations at arc_nodes 51, 101, 201: " << counts[0] << ", " << counts[1] << ", " << counts[2];
}

}  // namespace
