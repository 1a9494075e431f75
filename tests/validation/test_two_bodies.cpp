// Two identical elastic half-discs in node-to-node contact (tests/fixtures/two_bodies_scene.hpp):
// the mirror symmetry of identical bodies gives exact checks, Dundurs' β = 0 the physics a body on a
// rigid flat lacks (no tangential traction under normal loading), and every strategy works on the
// pair through the interface layer alone. Hertz and Cattaneo–Mindlin for the pair: test_hertz.cpp,
// test_cattaneo.cpp.
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "fixtures/two_bodies_scene.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/solver/contact_law_check.hpp"
#include "strategies/strategy_fixture.hpp"

namespace stc::validation {
namespace {

// The seed's motion without the slide: pressed 0.1 beyond first contact.
Scene pressedSeed(int arc_nodes, int steps, double friction) {
  Scene scene = test::seedScene(arc_nodes, steps);
  scene.contact.friction = friction;
  scene.dirichlet[0].history = {{0.0}, {0.0}};
  return scene;
}

double largestRow(const Eigen::MatrixXd& lambda, int first) {
  double largest = 0.0;
  for (Eigen::Index row = first; row < lambda.rows(); row += 2) largest = std::max(largest, lambda.row(row).cwiseAbs().maxCoeff());
  return largest;
}

// Without friction the pair's symmetric solution is the solution, and each body is the one body on
// a rigid flat through the plane of symmetry: the same interface forces to round-off (the pairs'
// normals are exactly y, the gaps exactly 2 g0 − 2 u_y by the mirror). 1e-9 relative: the incremental
// solver's Newton residual is ~1e-15, the two Delassus operators differ in their round-off.
TEST(TwoBodies, AFrictionlessMirrorPairCarriesTheOneBodyForces) {
  const Scene one = pressedSeed(31, 21, 0.0);
  const Problem body = buildProblem(one), pair = buildProblem(test::mirroredPair(one));
  ASSERT_TRUE(pair.contact.isPair());
  ASSERT_EQ(pair.contact.size(), body.contact.size());
  const SolveResult a = solveIncremental(body), b = solveIncremental(pair);
  ASSERT_TRUE(a.summary.converged() && b.summary.converged());
  const double scale = a.interface.lambda.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  const double difference = (a.interface.lambda - b.interface.lambda).cwiseAbs().maxCoeff() / scale;
  std::cout << "[ measured ] the pair's forces differ from the one body's by " << difference << " of the largest\n";
  EXPECT_LE(difference, 1e-9);
  // The relative displacement of the pair is the one body's displacement doubled.
  const double v_scale = a.interface.v.cwiseAbs().maxCoeff();
  for (Eigen::Index row = 0; row < a.interface.v.rows(); row += 2)
    EXPECT_LE((2.0 * a.interface.v.row(row) - b.interface.v.row(row)).cwiseAbs().maxCoeff(), 1e-9 * v_scale) << row;
}

// Dundurs' β = 0 for identical bodies: pressing them together with friction locks in no tangential
// traction (by the mirror symmetry and Newton's third law), while the same body pressed on a rigid
// flat (β = 0.29 at ν = 0.3) locks in a tangential force of the order of μ λ_n as its surface slips
// inward (Spence's problem, test_cattaneo.cpp). The one-body bound shows the check can fail.
TEST(TwoBodies, IdenticalBodiesPressedWithFrictionLockInNoTangentialTraction) {
  const Scene one = pressedSeed(31, 21, 0.5);
  const SolveResult body = solveIncremental(buildProblem(one));
  const SolveResult pair = solveIncremental(buildProblem(test::mirroredPair(one)));
  ASSERT_TRUE(body.summary.converged() && pair.summary.converged());
  const double body_n = largestRow(body.interface.lambda, 0), pair_n = largestRow(pair.interface.lambda, 0);
  std::cout << "[ measured ] max |lambda_t| / max lambda_n: one body on a rigid flat "
            << largestRow(body.interface.lambda, 1) / body_n << ", two identical bodies "
            << largestRow(pair.interface.lambda, 1) / pair_n << "\n";
  EXPECT_GT(largestRow(body.interface.lambda, 1), 0.01 * body_n);
  EXPECT_LE(largestRow(pair.interface.lambda, 1), 1e-9 * pair_n);
}

// Every strategy on the pair pressed and slid (the seed's motion doubled, μ = 0.15, partial then
// gross slip): the tolerance bounds the true error against the incremental solver, the estimate is
// not below it, and the admissible iterate satisfies the contact law to the tolerance's order. No
// strategy code knows of bodies: the pair is the interface's B (rows n·(u_s − u_m)).
void expectEveryStrategyReachesTheIncrementalSolution(const test::StrategyFixture& pair) {
  ASSERT_TRUE(pair.problem.contact.isPair());
  for (const std::string name : {"latin", "latin-pgd", "fas-aposteriori", "fas-apriori"}) {
    const SolveResult r = pair.solve(name, 1e-6);
    ASSERT_TRUE(r.summary.converged()) << name << ": " << r.summary.message;
    ASSERT_TRUE(r.summary.error.has_value()) << name;
    EXPECT_LE(*r.summary.error, 1e-6) << name;
    EXPECT_GE(r.summary.error_estimate, *r.summary.error) << name;
    EXPECT_LT(checkContactLaw(pair.problem, r.admissible()).max(), 1e-4) << name;
    std::cout << "[ measured ] pair " << name << ": " << r.summary.relaxations << " relaxations, true error "
              << *r.summary.error << "\n";
  }
}

TEST(TwoBodies, EveryStrategyReachesTheIncrementalSolutionOfThePair) {
  expectEveryStrategyReachesTheIncrementalSolution(test::StrategyFixture(test::mirroredPair(test::seedScene(31, 41))));
}

// The same in 3D: two half-balls (divisions 4, 21 instants), pressed and slid.
TEST(TwoBodies, EveryStrategyReachesTheIncrementalSolutionOfThePairIn3d) {
  expectEveryStrategyReachesTheIncrementalSolution(test::StrategyFixture(test::mirroredPair(test::hemisphereScene(4, 21))));
}

}  // namespace
}  // namespace stc::validation

namespace stc::validation {
namespace {

// [master_material] equal to [material] assembles the same stiffness (the two bodies' parts summed)
// and gives the same forces; a stiffer master changes them.
TEST(TwoBodies, AMasterMaterialEqualToTheBodysChangesNothing) {
  const Scene one = test::mirroredPair(pressedSeed(31, 11, 0.15));
  Scene same = one;
  same.master_material = one.material;
  const Problem a = buildProblem(one), b = buildProblem(same);
  ASSERT_TRUE(b.master_material.has_value());
  const double scale = Eigen::MatrixXd(a.stiffness).cwiseAbs().maxCoeff();
  EXPECT_LE(Eigen::MatrixXd(a.stiffness - b.stiffness).cwiseAbs().maxCoeff(), 1e-14 * scale);
  EXPECT_LE((a.contact.search_direction - b.contact.search_direction).cwiseAbs().maxCoeff(),
            1e-14 * a.contact.search_direction.maxCoeff());
  Scene stiffer = one;
  stiffer.master_material = MaterialSpec{9000.0, 0.3};
  const SolveResult r_a = solveIncremental(a), r_s = solveIncremental(buildProblem(stiffer));
  EXPECT_GT(largestRow(r_s.interface.lambda, 0), 1.2 * largestRow(r_a.interface.lambda, 0));
}

}  // namespace
}  // namespace stc::validation
