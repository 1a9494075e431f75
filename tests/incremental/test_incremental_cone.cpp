// The incremental solver's cone law with lazily computed Delassus columns (src/incremental/cone_newton.hpp):
// the same solution as the plane law in 2D, and in 3D the contact law to round-off, the symmetry of
// the scene, Coulomb sliding at the end of the slide, and columns only for the nodes that close.
#include <gtest/gtest.h>

#include <iostream>
#include <regex>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/solver/contact_law_check.hpp"

namespace {

double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

// Rows d i + r of every node i (r = 0: normal, 1 and 2: tangential), summed per instant.
Eigen::RowVectorXd resultant(const Eigen::MatrixXd& lambda, int d, int r) {
  Eigen::RowVectorXd total = Eigen::RowVectorXd::Zero(lambda.cols());
  for (Eigen::Index i = 0; d * i < lambda.rows(); ++i) total += lambda.row(d * i + r);
  return total;
}

}  // namespace

// Two exact methods for the same discrete law: they agree to round-off amplified by the Newton
// systems' conditioning (measured 1.9e-15 on the forces; 1e-10 leaves room for other BLAS and
// compilers, and is far below any modelling difference).
TEST(IncrementalCone, AgreesWithThePlaneLawOnTheSeedScene) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(31, 41));
  const stc::SolveResult plane = stc::solveIncremental(problem);
  stc::IncrementalOptions options;
  options.cone_law = true;
  const stc::SolveResult cone = stc::solveIncremental(problem, options);
  ASSERT_EQ(cone.summary.termination, stc::Termination::Converged) << cone.summary.message;
  const double force = relativeDifference(cone.interface.lambda, plane.interface.lambda);
  const double displacement = relativeDifference(cone.interface.v, plane.interface.v);
  std::cout << "cone law vs plane law: relative difference " << force << " (forces), " << displacement
            << " (displacements)\n";
  EXPECT_LT(force, 1e-10);
  EXPECT_LT(displacement, 1e-10);
}

TEST(IncrementalCone, SolvesTheHemisphereToRoundOff) {
  const stc::Problem problem = stc::buildProblem(stc::test::hemisphereScene(4, 21));
  const stc::SolveResult r = stc::solveIncremental(problem);
  ASSERT_EQ(r.summary.termination, stc::Termination::Converged) << r.summary.message;
  EXPECT_LT(stc::checkContactLaw(problem, r.interface).max(), 1e-10);
  EXPECT_LE(r.summary.indicator, 1e-13);
}

// The scene is symmetric about the plane y = 0 and slides along x: no resultant along y (τ_2 = e_y
// for the normal e_z), and at t = 1 every closed node slips, so the x resultant is nearly −μ N
// (equal if all slip directions were parallel to x; never more, by the cone).
TEST(IncrementalCone, HemisphereSlidesAlongXWithCoulombFriction) {
  const stc::Problem problem = stc::buildProblem(stc::test::hemisphereScene(4, 21));
  const stc::SolveResult r = stc::solveIncremental(problem);
  const Eigen::RowVectorXd normal = resultant(r.interface.lambda, 3, 0);
  const Eigen::RowVectorXd along_x = resultant(r.interface.lambda, 3, 1), along_y = resultant(r.interface.lambda, 3, 2);
  EXPECT_LT(along_y.cwiseAbs().maxCoeff(), 1e-10 * normal.maxCoeff());
  const double N = normal(20), T = -along_x(20), mu = problem.contact.friction;
  EXPECT_GT(N, 0.0);
  EXPECT_LE(T, mu * N * (1.0 + 1e-12));
  EXPECT_GT(T, 0.95 * mu * N);
}

TEST(IncrementalCone, FrictionlessHemisphereHasNoTangentialForce) {
  const stc::Problem problem = stc::buildProblem(stc::test::hemisphereScene(3, 11, 0.0));
  const stc::SolveResult r = stc::solveIncremental(problem);
  ASSERT_EQ(r.summary.termination, stc::Termination::Converged) << r.summary.message;
  const double scale = r.interface.lambda.cwiseAbs().maxCoeff();
  EXPECT_GT(scale, 0.0);
  for (Eigen::Index i = 0; i < problem.contact.size(); ++i)  // zero up to the LU's round-off
    EXPECT_LT(r.interface.lambda.block(3 * i + 1, 0, 2, r.interface.lambda.cols()).cwiseAbs().maxCoeff(), 1e-12 * scale);
}

// Only the nodes that close get Delassus columns: the message reports "columns of N of n_C".
TEST(IncrementalCone, ComputesColumnsOnlyForNodesThatClose) {
  const stc::Problem problem = stc::buildProblem(stc::test::hemisphereScene(4, 21));
  const stc::SolveResult r = stc::solveIncremental(problem);
  std::smatch match;
  ASSERT_TRUE(std::regex_search(r.summary.message, match, std::regex("columns of ([0-9]+) of ([0-9]+) contact nodes")))
      << r.summary.message;
  const int computed = std::stoi(match[1]), total = std::stoi(match[2]);
  EXPECT_EQ(total, problem.contact.size());
  EXPECT_GE(computed, 13);  // the closed nodes at t = 1 (reactions.csv: n_contact = 15 at the last instant)
  EXPECT_LT(computed, total / 4);
}

// While the closed set stays, the Newton systems after the first are solved by updating its LU
// (row_updated_lu.hpp): the message reports "Newton systems: F LU factorisations, U solved by
// updating one (R updates rejected)", one system per Newton iteration with a closed node.
// The half-ball pressed by t = 0.2 and held, then two cycles of amplitude 0.004 along x (partial
// slip, as examples/scenes/hemisphere_fretting.toml): the closed set settles, the slip annulus moves.
TEST(IncrementalCone, UpdatesOneFactorAcrossNewtonSystemsWhileTheClosedSetStays) {
  stc::Scene scene = stc::test::hemisphereScene(4, 101);
  scene.dirichlet[0] = {"top", stc::Component::X,
                        {{0.0, 0.2, 0.4, 0.6, 0.8, 1.0}, {0.0, 0.0, 0.004, -0.004, 0.004, 0.0}}};
  scene.dirichlet[2] = {"top", stc::Component::Z, {{0.0, 0.05, 0.2, 1.0}, {0.0, -0.01, -0.06, -0.06}}};
  const stc::Problem problem = stc::buildProblem(scene);
  const stc::SolveResult r = stc::solveIncremental(problem);
  ASSERT_EQ(r.summary.termination, stc::Termination::Converged) << r.summary.message;
  std::smatch systems, newton;
  const std::regex counts(
      "Newton systems: ([0-9]+) LU factorisations, ([0-9]+) solved by updating one \\(([0-9]+) updates rejected\\)");
  ASSERT_TRUE(std::regex_search(r.summary.message, systems, counts))
      << r.summary.message;
  ASSERT_TRUE(std::regex_search(r.summary.message, newton, std::regex("([0-9]+) Newton iterations")));
  const int factorised = std::stoi(systems[1]), updated = std::stoi(systems[2]), rejected = std::stoi(systems[3]);
  std::cout << factorised << " factorised, " << updated << " updated, " << rejected << " rejected of "
            << newton[1] << " Newton iterations\n";
  EXPECT_GT(updated, 0);
  EXPECT_EQ(rejected, 0);
  EXPECT_LE(factorised + updated, std::stoi(newton[1]));
  EXPECT_LT(stc::checkContactLaw(problem, r.interface).max(), 1e-10);
}
