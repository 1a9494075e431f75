// Validation against an analytic solution in 3D: frictionless point contact of the half-ball (R = 1,
// E = 3000, ν = 0.3) pressed onto the rigid flat by δ = 0.005 beyond first contact, compared with
// Hertz for a sphere on a rigid plane (Johnson, Contact Mechanics, 1985, §4.2):
//   a = (3 P R / (4 E*))^(1/3),  p0 = 3 P / (2 π a²),  E* = E / (1 − ν²),
// P the computed total normal force. The mesh has a uniformly meshed core of half-width 0.07 R ≈ a
// around the pole (h = 0.07 R / divisions) and geometric shells outside (src/mesh/half_ball.hpp):
// the power grading of the plain half-ball leaves elements ~a at depth ~a and stalls at −8 % on a.
// a/R ≈ 0.07: the finite body perturbs Hertz by O((a/R)²) (≈ 0.5 %, as in 2D, test_hertz.cpp).
//
// Measured (docs/validation_3d.md; `--gtest_also_run_disabled_tests --gtest_filter='Hertz3d.*'`):
//   divisions      3      4      6      8
//   a/h          3.1    4.1    6.2    8.2
//   error a    −3.6 % −2.3 % −1.3 % −0.7 %
//   error p0   +5.9 % +3.8 % +1.8 % +1.0 %
// i.e. first order in h/a: |error a| ≈ (0.05–0.11) h/a and |error p0| ≈ (0.08–0.18) h/a.
#include <gtest/gtest.h>
#include <gsl/gsl_fit.h>

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/mesh/half_ball.hpp"
#include "stcontact/scene/scene.hpp"
#include "validation/msh_writer.hpp"
#include "validation/point_contact_3d.hpp"

namespace stc::validation {
namespace {

struct HertzComparison {
  double a = 0.0, p0 = 0.0;              // measured from the nodal forces
  double a_hertz = 0.0, p0_hertz = 0.0;  // Hertz with the computed P
  double h = 0.0;                        // the core's cell size
  double errorA() const { return a / a_hertz - 1.0; }
  double errorP0() const { return p0 / p0_hertz - 1.0; }
};

// a from the second moment of the nodal normal forces (discFromMoments). p0 by least squares of the
// nodal pressures λ_i / A_i against √(1 − r_i²/a²) over r_i < 0.8 a (gsl_fit_mul; the edge nodes'
// tributary pressure is biased low by the √ edge of p).
HertzComparison compareWithHertz(const Problem& problem, const Eigen::MatrixXd& lambda) {
  const auto& c = problem.contact;
  const int k = problem.numSteps() - 1;
  const std::vector<Eigen::Vector2d> xy = contactXY(problem);
  std::vector<double> w;
  for (int i = 0; i < c.size(); ++i) w.push_back(lambda(3 * i, k));
  const DiscFit fit = discFromMoments(xy, w);
  HertzComparison out;
  out.a = fit.radius;
  std::vector<double> shape, pressure;
  for (int i = 0; i < c.size(); ++i) {
    const double rho = (xy[i] - fit.centre).norm() / out.a;
    if (rho >= 0.8) continue;
    shape.push_back(std::sqrt(1.0 - rho * rho));
    pressure.push_back(lambda(3 * i, k) / c.tributary[i]);
  }
  double cov = 0.0, sumsq = 0.0;
  gsl_fit_mul(shape.data(), 1, pressure.data(), 1, shape.size(), &out.p0, &cov, &sumsq);
  const double nu = problem.material.poisson, e_star = problem.material.young / (1.0 - nu * nu);
  const double radius = 1.0;
  out.a_hertz = std::cbrt(3.0 * fit.total * radius / (4.0 * e_star));
  out.p0_hertz = 3.0 * fit.total / (2.0 * M_PI * out.a_hertz * out.a_hertz);
  return out;
}

HertzComparison solveAndCompare(int divisions, bool pair = false) {
  PointContactSetup setup;
  setup.divisions = divisions;
  setup.pair = pair;
  const Scene scene = pointContactScene(setup);
  const Problem problem = buildProblem(scene);
  const SolveResult result = solveIncremental(problem);
  EXPECT_TRUE(result.summary.converged()) << result.summary.message;
  HertzComparison c = compareWithHertz(problem, result.interface.lambda);
  c.h = coreCellSize(scene);
  std::printf("[ measured ] %sdivisions %d: %d dofs, %d contact nodes, a/h %.2f, error a %+.2f %%, error p0 %+.2f %%\n",
              pair ? "pair, " : "", divisions, 3 * problem.numNodes(), problem.contact.size(), c.a / c.h, 100 * c.errorA(),
              100 * c.errorP0());
  return c;
}

// Two half-balls meshed apart (upper: the validation mesh at `upper` divisions; lower: at `lower`,
// mirrored 2 g0 below it), written as one Gmsh file: their contact surfaces do not match, and the
// pair is node to surface (contact.pairing = "segment") along z.
Scene nonMatchingPair(int upper, int lower) {
  PointContactSetup setup;
  setup.divisions = upper;
  setup.pair = true;
  Scene scene = pointContactScene(setup);
  HalfBallOptions options{scene.mesh.radius, upper, scene.mesh.grading, scene.mesh.core};
  TetMesh mesh = makeHalfBall(options);
  options.divisions = lower;
  const TetMesh image = makeHalfBall(options);
  const int offset = mesh.numNodes();
  const double gap = *scene.mesh.mirror_gap;
  mesh.nodes.conservativeResize(3, offset + image.numNodes());
  mesh.nodes.rightCols(image.numNodes()) = image.nodes;
  mesh.nodes.bottomRightCorner(1, image.numNodes()).array() = -2.0 * scene.mesh.radius - gap - image.nodes.row(2).array();
  mesh.tets.conservativeResize(4, mesh.numElements() + image.numElements());
  mesh.tets.rightCols(image.numElements()) = image.tets.array() + offset;
  for (const auto& [name, group] : image.groups) {
    SurfaceGroup& mirrored = mesh.groups["mirror_" + name];
    for (const auto& t : group.triangles) mirrored.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  const auto file = std::filesystem::path(STC_BINARY_DIR) / ("two_balls_" + std::to_string(upper) + "_" + std::to_string(lower) + ".msh");
  writeMsh(file, mesh);
  scene.mesh.generator.clear();
  scene.mesh.mirror_gap.reset();
  scene.mesh.file = file;
  scene.contact.to_segment = true;
  return scene;
}

}  // namespace

// Hertz for two half-balls meshed apart, node to surface: each pair's a and p0 (h the coarser core's
// cell size).
HertzComparison nonMatchingHertz(int upper, int lower) {
  const Scene scene = nonMatchingPair(upper, lower);
  const Problem problem = buildProblem(scene);
  int between = 0;  // slave nodes compared with more than one master node
  for (int i = 0; i < problem.contact.size(); ++i) between += problem.contact.master_weights(1, i) > 0.0 ? 1 : 0;
  EXPECT_GT(between, problem.contact.size() / 2);
  const SolveResult result = solveIncremental(problem);
  EXPECT_TRUE(result.summary.converged()) << result.summary.message;
  HertzComparison c = compareWithHertz(problem, result.interface.lambda);
  c.h = scene.mesh.core * scene.mesh.radius / std::min(upper, lower);
  std::printf("[ measured ] non-matching pair, divisions %d on %d: %d of %d slave nodes between master nodes, a/h %.2f, "
              "error a %+.2f %%, error p0 %+.2f %%\n", upper, lower, between, problem.contact.size(), c.a / c.h,
              100 * c.errorA(), 100 * c.errorP0());
  return c;
}

// The slave coarser than the master (divisions 4 on 5; 66k dofs): Hertz within first-order bounds, a
// as above (0.15 h/a) and p0 within 0.3 h/a: node to surface adds the ripple of a slave node's
// pressure between master nodes (measured constants: 0.09 for a, 0.20 for p0; 5 on 4 gives 0.12 and
// 0.24, the largest seen; 6 on 5, 0.10 and 0.18). Refined: DISABLED_TwoSpheresOnNonMatchingMeshes...
TEST(Hertz3d, TwoSpheresOnNonMatchingMeshesWithinFirstOrderBounds) {
  const HertzComparison c = nonMatchingHertz(4, 5);
  EXPECT_LE(std::abs(c.errorA()), 0.15 * c.h / c.a);
  EXPECT_LE(std::abs(c.errorP0()), 0.3 * c.h / c.a);
}

// Full size (docs/two_bodies.md, "Non-matching meshes"): the errors fall under refinement, 6 on 5
// then 8 on 7 (measured: a −1.98 %, −1.13 %; p0 +3.58 %, +2.04 %).
TEST(Hertz3d, DISABLED_TwoSpheresOnNonMatchingMeshesConvergeTowardHertz) {
  const HertzComparison coarse = nonMatchingHertz(6, 5), fine = nonMatchingHertz(8, 7);
  EXPECT_LT(std::abs(fine.errorA()), std::abs(coarse.errorA()));
  EXPECT_LT(std::abs(fine.errorP0()), std::abs(coarse.errorP0()));
}

// Small settings (a/h = 3.1 and 4.1, 8k and 16k dofs): the errors fall under refinement and stay
// within first-order bounds, |error a| <= 0.15 h/a and |error p0| <= 0.25 h/a (the largest measured
// constants, 0.11 and 0.18 at divisions 3 (header), with a third of margin).
TEST(Hertz3d, ContactRadiusAndPeakPressureConvergeTowardHertz) {
  const HertzComparison coarse = solveAndCompare(3), fine = solveAndCompare(4);
  for (const HertzComparison& c : {coarse, fine}) {
    EXPECT_LE(std::abs(c.errorA()), 0.15 * c.h / c.a);
    EXPECT_LE(std::abs(c.errorP0()), 0.25 * c.h / c.a);
  }
  EXPECT_LT(std::abs(fine.errorA()), std::abs(coarse.errorA()));
  EXPECT_LT(std::abs(fine.errorP0()), std::abs(coarse.errorP0()));
}

// Two identical elastic half-balls pressed together (node to node): for them R* = R/2 and
// 1/E* = 2 (1 − ν²)/E, so a³ = 3 P R*/(4 E*) is the one body's on a rigid flat and compareWithHertz
// applies unchanged; the same bounds and the same refinement.
TEST(Hertz3d, TwoIdenticalSpheresConvergeTowardHertz) {
  const HertzComparison coarse = solveAndCompare(3, true), fine = solveAndCompare(4, true);
  for (const HertzComparison& c : {coarse, fine}) {
    EXPECT_LE(std::abs(c.errorA()), 0.15 * c.h / c.a);
    EXPECT_LE(std::abs(c.errorP0()), 0.25 * c.h / c.a);
  }
  EXPECT_LT(std::abs(fine.errorA()), std::abs(coarse.errorA()));
  EXPECT_LT(std::abs(fine.errorP0()), std::abs(coarse.errorP0()));
}

// Full size (docs/validation_3d.md): a and p0 within 2 % of Hertz from divisions 6 on (48k and 107k
// dofs, ≈ 15 s and 70 s, 0.9 and 3.1 GB).
TEST(Hertz3d, DISABLED_WithinTwoPercentOnRefinedMeshes) {
  for (int divisions : {6, 8}) {
    const HertzComparison c = solveAndCompare(divisions);
    EXPECT_LE(std::abs(c.errorA()), 0.02);
    EXPECT_LE(std::abs(c.errorP0()), 0.02);
  }
}

// The same for two identical half-balls (twice the dofs; docs/two_bodies.md).
TEST(Hertz3d, DISABLED_TwoIdenticalSpheresWithinTwoPercentOnRefinedMeshes) {
  for (int divisions : {6, 8}) {
    const HertzComparison c = solveAndCompare(divisions, true);
    EXPECT_LE(std::abs(c.errorA()), 0.02);
    EXPECT_LE(std::abs(c.errorP0()), 0.02);
  }
}

}  // namespace stc::validation
