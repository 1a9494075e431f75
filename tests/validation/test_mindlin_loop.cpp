// Validation against Mindlin's hysteresis loop (K. L. Johnson, Contact Mechanics, 1985, §7.4): two
// identical elastic half-balls (R = 1, E = 3000, ν = 0.3, μ = 0.5; tests/fixtures/two_bodies_scene.hpp,
// β = 0, where Mindlin's solution is exact) pressed together, then the upper one driven sideways
// back and forth at constant pressing: δ from 0 to +δ*, to −δ*, back to +δ*, so that the tangential
// force Q runs a closed loop between ±Q* < μP (partial slip throughout). With the compliance of two
// identical bodies, K = 3 μ P (2 − ν) / (8 G a) (Johnson eq. 7.42 with both bodies' terms),
//   initial loading  δ = f(Q) = K [1 − (1 − Q/μP)^{2/3}],
//   unloading from Q*  δ = δ* − 2 f((Q* − Q)/2),  reloading from −Q*  δ = −δ* + 2 f((Q* + Q)/2)
// (Johnson eq. 7.59), so the loop encloses (Johnson eq. 7.62, twice for two bodies)
//   W = K [ (24 μ P / 5) (1 − r^{5/3}) − 4 Q* (1 + r^{2/3}) ],   r = 1 − Q*/μP,
// and is 2 δ* − 4 f(Q*/2) wide at Q = 0. The drive moves the bodies' far faces, which adds an elastic
// compliance of the finite bodies, linear in Q, to Mindlin's: it encloses no area and shifts both
// branches equally, so the area and the width at Q = 0 compare with Mindlin's directly.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "fixtures/two_bodies_scene.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/scene/scene.hpp"
#include "validation/hysteresis_loop.hpp"
#include "validation/point_contact_3d.hpp"

namespace stc::validation {
namespace {

constexpr int kPressSteps = 5;
constexpr int kQuarterSteps = 20;  // 0 → +δ*, then 2 × 20 for each half cycle
constexpr double kFriction = 0.5;
constexpr double kDrive = 0.0024;  // δ* of the one-body scene, doubled for the pair: Q*/μP ≈ 0.79

Scene loopScene(int divisions) {
  PointContactSetup setup;
  setup.divisions = divisions;
  setup.friction = kFriction;
  setup.press_steps = kPressSteps;
  setup.slide_steps = 5 * kQuarterSteps;
  Scene scene = pointContactScene(setup);  // one body; its drive along x replaced by the cycle
  const double t = 1.0 / (kPressSteps + 5 * kQuarterSteps), t_press = kPressSteps * t, q = kQuarterSteps * t;
  scene.dirichlet[0].history = {{0.0, t_press, t_press + q, t_press + 3 * q, t_press + 5 * q},
                                {0.0, 0.0, kDrive, -kDrive, kDrive}};
  return test::mirroredPair(scene);
}

struct Loop {
  HysteresisLoop cycle;
  double P = 0.0, a = 0.0;  // the normal force and the contact radius at the end
};

Loop measureLoop(int divisions) {
  const Problem problem = buildProblem(loopScene(divisions));
  const SolveResult result = solveIncremental(problem);
  EXPECT_TRUE(result.summary.converged()) << result.summary.message;
  const Eigen::MatrixXd& lambda = result.interface.lambda;
  const int top = std::get<TetMesh>(problem.body).group("top").nodes.front();
  std::vector<double> q, delta;
  for (int k = kPressSteps; k < problem.numSteps(); ++k) {
    double force = 0.0;  // the master's force on the upper body is −λ_t: Q > 0 resists a drive along +x
    for (int i = 0; i < problem.contact.size(); ++i) force -= lambda(3 * i + 1, k);
    q.push_back(force);
    delta.push_back(problem.fullDisplacement(Eigen::VectorXd::Zero(problem.numFreeDofs()), k)[3 * top]);
  }
  Loop loop{hysteresisLoop(std::move(q), std::move(delta), kQuarterSteps)};
  const int k = problem.numSteps() - 1;
  std::vector<double> normal;
  for (int i = 0; i < problem.contact.size(); ++i) normal.push_back(lambda(3 * i, k));
  const DiscFit fit = discFromMoments(contactXY(problem), normal);
  loop.P = fit.total;
  loop.a = fit.radius;
  return loop;
}

struct Mindlin {
  double area = 0.0, width = 0.0;
};

Mindlin mindlin(const Loop& loop, double poisson) {
  const double mu_p = kFriction * loop.P, shear = 3000.0 / (2.0 * (1.0 + poisson));
  const double K = 3.0 * mu_p * (2.0 - poisson) / (8.0 * shear * loop.a);
  const auto f = [&](double q) { return K * (1.0 - std::pow(1.0 - q / mu_p, 2.0 / 3.0)); };
  const double r = 1.0 - loop.cycle.q_star / mu_p;
  Mindlin m;
  m.area = K * (24.0 * mu_p / 5.0 * (1.0 - std::pow(r, 5.0 / 3.0)) - 4.0 * loop.cycle.q_star * (1.0 + std::pow(r, 2.0 / 3.0)));
  m.width = 2.0 * f(loop.cycle.q_star) - 4.0 * f(0.5 * loop.cycle.q_star);
  return m;
}

struct LoopErrors {
  double area = 0.0, width = 0.0;  // relative to Mindlin's
  Loop loop;
};

LoopErrors compareWithMindlin(int divisions) {
  LoopErrors e;
  e.loop = measureLoop(divisions);
  const Mindlin m = mindlin(e.loop, 0.3);
  e.area = e.loop.cycle.area / m.area - 1.0;
  e.width = e.loop.cycle.width / m.width - 1.0;
  std::printf("[ measured ] divisions %d: Q*/muP %.3f, a %.4f; loop area %.4e (Mindlin %.4e, %+.1f %%), width at Q = 0 "
              "%.4e (Mindlin %.4e, %+.1f %%); closure %.1e, Masing %.1e\n",
              divisions, e.loop.cycle.q_star / (kFriction * e.loop.P), e.loop.a, e.loop.cycle.area, m.area, 100 * e.area,
              e.loop.cycle.width, m.width, 100 * e.width, e.loop.cycle.closure, e.loop.cycle.masing);
  return e;
}

}  // namespace

// Small settings (divisions 3 and 4, a/h = 3.1 and 4.1, Q*/μP = 0.79, 20 instants a quarter cycle):
// (1) the loop closes: Q back at Q* after the cycle (measured 1.9e-5, 1.2e-5 of Q*);
// (2) Masing's rule, on which Mindlin's loop rests, holds for the discrete model too: the unloading
//     branch is its own initial loading curve scaled by 2 (measured 3.3e-3, 2.1e-3 of δ*, the
//     interpolation between instants; 1.0e-3 at divisions 8);
// (3) area and width at Q = 0 against Mindlin within a first-order mesh error, |error| ≤ h/a. The
//     finite elements are stiffer than the half-space under the stick zone's correction traction,
//     resolved by c/h = 0.59 a/h nodes, so their loop is wider. Measured (area, width):
//     +20.8 %, +11.0 % (a/h 3.1); +19.1 %, +13.6 % (4.1); +11.8 %, +11.3 % (6.2); +9.3 %, +9.0 % (8.2):
//     at most 0.78 h/a, first order from divisions 4 on, extrapolated to h = 0: +1.6 %, +1.9 %
//     (docs/two_bodies.md, "Mindlin's loop").
TEST(MindlinLoop, TwoIdenticalSpheresRunMindlinsLoop) {
  for (int divisions : {3, 4}) {
    const LoopErrors e = compareWithMindlin(divisions);
    const double h_over_a = coreCellSize(loopScene(divisions)) / e.loop.a;
    EXPECT_LE(e.loop.cycle.closure, 1e-3);
    EXPECT_LE(e.loop.cycle.masing, 1e-2);
    EXPECT_LE(std::abs(e.area), h_over_a) << "divisions " << divisions;
    EXPECT_LE(std::abs(e.width), h_over_a) << "divisions " << divisions;
  }
}

// Full size (docs/two_bodies.md): divisions 6 and 8 (97k and 214k dofs).
TEST(MindlinLoop, DISABLED_TwoIdenticalSpheresOnRefinedMeshes) {
  for (int divisions : {6, 8}) compareWithMindlin(divisions);
}

}  // namespace stc::validation
