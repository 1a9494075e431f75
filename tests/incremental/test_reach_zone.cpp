// The incremental solver on the nodes within reach of the prescribed motion
// (src/incremental/reach_zone.hpp): the zone is a strict part of the seed's interface, the solution
// lifted to every node is the whole interface's to round-off, for fewer sparse solves; a zone that
// is too small is found out by the nodes it leaves penetrating.
#include "stcontact/incremental/reach_zone.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/linalg/backends/cholmod_factor.hpp"

namespace {

stc::IncrementalOptions onEveryNode() {
  stc::IncrementalOptions options;
  options.zone_within_reach = false;
  return options;
}

double largestDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).cwiseAbs().maxCoeff(); }

TEST(ReachZone, TheSeedsZoneIsAStrictPartOfItsInterface) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(101, 41));
  const auto zone = stc::reachZone(problem);
  ASSERT_TRUE(zone.has_value());
  EXPECT_GT(zone->size(), 0u);
  EXPECT_LT(static_cast<int>(zone->size()), problem.contact.size());
  EXPECT_TRUE(std::is_sorted(zone->begin(), zone->end()));
}

TEST(ReachZone, AnAppliedForceGivesNoZone) {
  stc::Scene scene = stc::test::seedScene(41, 21);
  stc::LoadSpec load;
  load.boundary = "top";
  load.component = stc::Component::Y;
  load.history = {{0.0, 1.0}, {0.0, -1.0}};
  scene.loads.push_back(load);
  EXPECT_FALSE(stc::reachZone(stc::buildProblem(scene)).has_value());
}

// Forces equal to 1e-12 of the largest force, displacements to 1e-12 of the largest: the same
// active sets, the Newton systems of the zone's rows, the far rows from the same solves.
TEST(IncrementalWithinReach, SolvesTheWholeProblemToRoundOffWithFewerSparseSolves) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(101, 81));
  const stc::SolveResult zone = stc::solveIncremental(problem);
  const stc::SolveResult whole = stc::solveIncremental(problem, onEveryNode());
  ASSERT_TRUE(zone.summary.converged()) << zone.summary.message;
  ASSERT_TRUE(whole.summary.converged()) << whole.summary.message;
  const double force = whole.interface.lambda.cwiseAbs().maxCoeff(), motion = whole.interface.v.cwiseAbs().maxCoeff();
  EXPECT_LE(largestDifference(zone.interface.lambda, whole.interface.lambda), 1e-12 * force);
  EXPECT_LE(largestDifference(zone.interface.v, whole.interface.v), 1e-12 * motion);
  const int zone_nodes = static_cast<int>(stc::reachZone(problem)->size());
  EXPECT_EQ(zone.summary.sparseSolves(), 2 * zone_nodes + static_cast<int>(problem.loads.size()));
  EXPECT_LT(zone.summary.sparseSolves(), whole.summary.sparseSolves());
  ASSERT_EQ(zone.summary.stages.size(), 1u);
  EXPECT_EQ(zone.summary.stages[0].nodes, zone_nodes);
  EXPECT_NE(zone.summary.message.find("solved on " + std::to_string(zone_nodes) + " of 101 contact nodes"),
            std::string::npos)
      << zone.summary.message;
  EXPECT_TRUE(whole.summary.stages.empty());
}

// In 3D the cone law marches on the zone with its Delassus operator from the factor's trailing block
// (no solve but the load terms' and the lift's, at most one per instant with a force), its scaling learnt before the
// march (a node whose columns exist but whose ρ were not learnt would stay open): the same solution
// to round-off as columns computed as nodes close.
TEST(IncrementalWithinReach, TheConeLawTakesTheZonesOperatorFromTheFactorAndSolvesTheSameProblem) {
  const stc::Problem problem = stc::buildProblem(stc::test::hemisphereScene(8, 21));
  const stc::SolveResult zone = stc::solveIncremental(problem);
  const stc::SolveResult lazy = stc::solveIncremental(problem, onEveryNode());
  ASSERT_TRUE(zone.summary.converged()) << zone.summary.message;
  ASSERT_TRUE(lazy.summary.converged()) << lazy.summary.message;
  const double force = lazy.interface.lambda.cwiseAbs().maxCoeff();
  ASSERT_GT(force, 0.0);
  EXPECT_LE(largestDifference(zone.interface.lambda, lazy.interface.lambda), 1e-11 * force);
  EXPECT_LE(largestDifference(zone.interface.v, lazy.interface.v), 1e-11 * lazy.interface.v.cwiseAbs().maxCoeff());
  const int zone_nodes = static_cast<int>(stc::reachZone(problem)->size());
  const int loads = static_cast<int>(problem.loads.size());
  int loaded_instants = 0;
  for (int k = 0; k < problem.numSteps(); ++k) loaded_instants += zone.interface.lambda.col(k).any();
  EXPECT_GT(zone.summary.sparseSolves(), loads);
  EXPECT_LE(zone.summary.sparseSolves(), loads + std::min(loaded_instants, 3 * zone_nodes));
  EXPECT_LT(zone.summary.sparseSolves(), lazy.summary.sparseSolves());
  EXPECT_NE(zone.summary.message.find("Delassus operator of the " + std::to_string(zone_nodes) +
                                      " zone nodes from the factorisation"),
            std::string::npos)
      << zone.summary.message;
  EXPECT_NE(lazy.summary.message.find("Delassus columns of"), std::string::npos);
}

// Lifting the solution of the zone's problem gives every node's displacement, and the whole
// solution's nodes left out stay out of the obstacle; a zone of the three middle nodes alone leaves
// their neighbours, which the motion presses too, penetrating. The same with W_ZZ from the solves
// (which give W_FZ) and from the factor's trailing block (the lift then solves as many right-hand
// sides as the zone's force history has rank: at most its 41 instants and 2 |Z| rows).
TEST(ZoneCondensation, LiftsToEveryNodeAndFindsTheNodesATooSmallZoneLeavesPenetrating) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(101, 41));
  const stc::CholmodFactor factor(problem.stiffness_free, "K_ff");
  const stc::SolveResult whole = stc::solveIncremental(problem, onEveryNode());
  for (const std::vector<int>& zone : {*stc::reachZone(problem), std::vector<int>{49, 50, 51}}) {
    stc::Problem part = problem;
    part.contact = stc::restrictToNodes(problem.contact, zone);
    const stc::CholmodFactor trailing(problem.stiffness_free, "K_ff", stc::dofsReadBy(part.contact.B), 0.0);
    const stc::SolveResult on_zone = stc::solveIncremental(part, onEveryNode());
    ASSERT_TRUE(on_zone.summary.converged()) << on_zone.summary.message;
    for (const stc::CholmodFactor* f : {&factor, &trailing}) {
      const stc::ZoneCondensation c = stc::ZoneCondensation::build(problem, *f, zone);
      const Eigen::SparseMatrix<double>& B_zone = part.contact.B;
      const Eigen::MatrixXd W_solves = stc::symmetricDelassus(B_zone, factor.solve(Eigen::MatrixXd(B_zone.transpose())));
      EXPECT_LE(largestDifference(c.on_zone.delassus, W_solves), 1e-12 * W_solves.cwiseAbs().maxCoeff());
      long lift_solves = 0;
      const stc::InterfaceHistory lifted = c.lift(problem.contact, *f, on_zone.interface, problem.numSteps(), lift_solves);
      const int by_columns = 2 * static_cast<int>(zone.size());
      int loaded_instants = 0;  // the rank of λ_Z is at most the number of its nonzero columns
      for (int k = 0; k < problem.numSteps(); ++k) loaded_instants += on_zone.interface.lambda.col(k).any();
      if (f == &factor) {
        EXPECT_EQ(lift_solves, 0);
      } else {
        EXPECT_GE(lift_solves, 1);
        EXPECT_LE(lift_solves, std::min(loaded_instants, by_columns));
        EXPECT_LT(loaded_instants, problem.numSteps());  // no force before the body touches
      }
      EXPECT_EQ(c.on_zone.sparse_solves, static_cast<int>(problem.loads.size()) + (f == &factor ? by_columns : 0));
      const std::vector<int> wrong = stc::penetratingNodes(problem.contact, lifted, c.far, 1e-12);
      if (zone.size() > 3) {
        EXPECT_TRUE(wrong.empty());
        EXPECT_LE(largestDifference(lifted.v, whole.interface.v), 1e-12 * whole.interface.v.cwiseAbs().maxCoeff());
      } else {
        EXPECT_FALSE(wrong.empty());
        EXPECT_TRUE(std::find(wrong.begin(), wrong.end(), 48) != wrong.end() ||
                    std::find(wrong.begin(), wrong.end(), 52) != wrong.end());
        for (int i : wrong) EXPECT_TRUE(std::find(zone.begin(), zone.end(), i) == zone.end()) << i;
      }
    }
  }
}

}  // namespace
