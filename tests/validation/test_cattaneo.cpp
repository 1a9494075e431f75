// Validation against Cattaneo–Mindlin partial slip: the half-disc (R = 1, E = 3000, plane strain) is
// pressed with friction onto the rigid flat to a fixed indentation δ (u_x = 0), then the indentation
// is held and the top edge is driven sideways slowly, so that the tangential force Q grows from 0
// towards μP. Cattaneo (1938) / Mindlin (1949), 2D: the central stick zone has half-width
//   c / a = √(1 − Q / (μ P)),
// the slip zones c < |x − e| < a carry q = μp, and the stick zone carries the traction deficit
//   μ p(x) − q(x) = μ p0 (c/a) √(1 − (x − e)²/c²),
// a semicircle law again, so that c is estimated like the Hertz half-width (semicircleFromMoments).
//
// Why the agreement cannot be exact here. Cattaneo's solution assumes that normal and tangential
// problems uncouple, i.e. Dundurs' β = 0. An elastic body on a RIGID base has
//   β = (1 − 2ν) / (2 (1 − ν)) = 0.286 for ν = 0.3, 0.091 for ν = 0.45.
// With β ≠ 0, (i) while the disc is pressed with friction, the surface points move inward as the
// contact grows, the outer ring slips inward and friction locks in an odd tangential traction
// (Spence's problem; after pressing c/a is 0.89 at ν = 0.3, μ = 0.5, measured); (ii) under the
// tangential load that locked-in traction adds to the new one on one side, so the stick zone shifts
// off-centre and shrinks faster than √(1 − Q/μP). The size of the effect is set by β/μ (Spence 1975,
// Nowell–Hills–Sackfield 1988). Approaching β = 0 means ν → 0.5, where P1 elements lock (at
// ν = 0.49 the measured c/a was worse again, 0.06 under theory at Q/μP = 0.8). ν = 0.45 (β/μ = 0.18)
// is the compromise validated quantitatively; ν = 0.3 (β/μ = 0.57) is checked qualitatively.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "fixtures/seed_scene.hpp"
#include "fixtures/two_bodies_scene.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "validation/validation_support.hpp"

namespace stc::validation {
namespace {

constexpr int kArcNodes = 801;        // h/a = 0.057 (a/R ≈ 0.07 as in the Hertz test)
constexpr double kIndentation = 0.008;
constexpr int kPressSteps = 10;       // pressing phase, instants 0 … 10
constexpr int kSlideSteps = 400;      // tangential phase: ΔQ/μP ≈ 0.0025 per instant
constexpr double kFriction = 0.5;
// Sideways drive at the end, u_x = 0.015 μ: Q reaches 0.90 μP (ν = 0.45) or μP (ν = 0.3), so the
// instants with Q/μP ≈ 0.2, 0.5, 0.8 lie inside the partial-slip phase.
constexpr double kDrivePerFriction = 0.015;

Scene cattaneoScene(double poisson, bool pair = false) {
  Scene scene = test::seedScene(kArcNodes, kPressSteps + kSlideSteps + 1);
  scene.material.poisson = poisson;
  scene.contact.friction = kFriction;
  scene.mesh.grading = 1.05;  // see test_hertz.cpp
  const double g0 = -(scene.obstacle.point.y() + scene.mesh.radius);
  const double t_press = double(kPressSteps) / (kPressSteps + kSlideSteps);
  scene.dirichlet[0].history = {{0.0, t_press, 1.0}, {0.0, 0.0, kDrivePerFriction * kFriction}};
  scene.dirichlet[1].history = {{0.0, t_press, 1.0}, {0.0, -(g0 + kIndentation), -(g0 + kIndentation)}};
  return pair ? test::mirroredPair(scene) : scene;
}

struct StickZone {
  double load_ratio = 0.0;  // |Q| / (μ P)
  double c_over_a = 0.0;    // moments: traction deficit over normal force
  double count_c_over_a = 0.0;  // Σ ℓ over sticking nodes / Σ ℓ over closed nodes
  double shift = 0.0;       // centre of the stick zone relative to the contact's, over a
  double half_width = 0.0;  // a
  int sticking = 0;
  double theory() const { return std::sqrt(std::max(0.0, 1.0 - load_ratio)); }
};

StickZone measureStickZone(const Problem& problem, const InterfaceHistory& h, int k) {
  const double mu = problem.contact.friction, step = problem.contact.tributary.maxCoeff();
  const Resultant r = resultant(h.lambda, k);
  const double sign = r.tangential >= 0.0 ? 1.0 : -1.0;
  const std::vector<double> x = contactX(problem), normal = normalForces(h.lambda, k);
  std::vector<double> deficit;
  for (int i = 0; i < problem.contact.size(); ++i) deficit.push_back(mu * h.lambda(2 * i, k) - sign * h.lambda(2 * i + 1, k));
  const SemicircleFit contact = semicircleFromMoments(x, normal, step);
  const SemicircleFit stick = semicircleFromMoments(x, deficit, step);
  StickZone z;
  z.load_ratio = std::abs(r.tangential) / (mu * r.normal);
  z.c_over_a = stick.half_width / contact.half_width;
  z.shift = (stick.centre - contact.centre) / contact.half_width;
  z.half_width = contact.half_width;
  double closed_length = 0.0, stick_length = 0.0;
  const std::vector<ContactState> states = contactStates(problem, h, k);
  for (int i = 0; i < problem.contact.size(); ++i) {
    if (states[i] != ContactState::Open) closed_length += problem.contact.tributary[i];
    if (states[i] != ContactState::Stick) continue;
    stick_length += problem.contact.tributary[i];
    ++z.sticking;
  }
  z.count_c_over_a = stick_length / closed_length;
  return z;
}

struct PartialSlipRun {
  std::vector<StickZone> zones;  // one per instant of the sideways phase
  int stick_count_increases = 0;
  double spacing = 0.0;  // h, the arc's node spacing
};

PartialSlipRun runPartialSlip(double poisson, bool pair = false) {
  const Problem problem = buildProblem(cattaneoScene(poisson, pair));
  const SolveResult result = solveIncremental(problem);
  EXPECT_TRUE(result.summary.converged()) << result.summary.message;
  PartialSlipRun run;
  run.spacing = M_PI * 1.0 / (kArcNodes + 1.0);  // R = 1, arc_nodes + 1 equal segments (mesh/half_disc.hpp)
  // From the first sideways instant: at the last pressing instant the states still show the inward
  // slip of pressing (a node that slipped inward then sticks when the drive turns sideways).
  for (int k = kPressSteps + 1; k < problem.numSteps(); ++k) {
    run.zones.push_back(measureStickZone(problem, result.interface, k));
    if (run.zones.size() > 1 && run.zones.back().sticking > run.zones[run.zones.size() - 2].sticking)
      ++run.stick_count_increases;
  }
  return run;
}

// The instant of the tangential phase whose Q/μP is nearest `target`.
const StickZone& nearest(const PartialSlipRun& run, double target) {
  return *std::min_element(run.zones.begin(), run.zones.end(), [target](const StickZone& a, const StickZone& b) {
    return std::abs(a.load_ratio - target) < std::abs(b.load_ratio - target);
  });
}

void print(double poisson, const StickZone& z) {
  std::cout << "[ measured ] nu " << poisson << ", Q/muP " << z.load_ratio << ": c/a theory " << z.theory()
            << ", moments " << z.c_over_a << ", node count " << z.count_c_over_a << " (" << z.sticking
            << " sticking nodes), stick-zone shift " << z.shift << " a\n";
}

const double kTargets[] = {0.2, 0.5, 0.8};

// Tolerance 0.05 on c/a (absolute), at ν = 0.45, μ = 0.5. Error sources:
// (1) discretisation, O(h/c): the same run at arc_nodes 401 was off by 0.023, 0.042, 0.077 at
//     Q/μP = 0.2, 0.5, 0.8 (μ = 0.4), about twice the 801 values, so ≲ 0.03 here;
// (2) β-coupling (header): a systematic shrinkage; the stick zone shifts by 0.05–0.08 a;
// (3) the node-count estimate is quantised: one node changes c by h/2, c/a by 0.03;
// (4) Q/μP moves by 0.0025 per instant: ≤ 0.003 in √(1 − Q/μP) at 0.8.
// Measured: moments −0.011, −0.018, −0.023; node count −0.006, −0.013, −0.031.
constexpr double kStickZoneTolerance = 0.05;

TEST(CattaneoMindlin, CattaneoMindlinStickZoneMatchesTheoryWhenDundursBetaIsSmall) {
  const double poisson = 0.45;
  const PartialSlipRun run = runPartialSlip(poisson);
  // The slip zone only grows under a monotone tangential drive.
  EXPECT_EQ(run.stick_count_increases, 0);
  for (double target : kTargets) {
    const StickZone& z = nearest(run, target);
    print(poisson, z);
    ASSERT_NEAR(z.load_ratio, target, 0.01);
    EXPECT_NEAR(z.c_over_a, z.theory(), kStickZoneTolerance) << "Q/muP " << z.load_ratio;
    EXPECT_NEAR(z.count_c_over_a, z.theory(), kStickZoneTolerance) << "Q/muP " << z.load_ratio;
  }
}

// ν = 0.3 (β/μ = 0.57): what can be asserted is qualitative. The stick zone shrinks monotonically
// as Q grows; it is smaller than Cattaneo's by more than the ν = 0.45 tolerance (the coupling is
// real, not noise: measured c/a = 0.84, 0.77, 0.72 × √(1 − Q/μP) at Q/μP = 0.2, 0.5, 0.8, and
// 0.89 already after pressing), but not by more than a factor 0.6 (a band around the measurement,
// a regression guard rather than a theory); and it sits off-centre by more than at ν = 0.45
// (measured 0.26–0.28 a against 0.05–0.08 a).
TEST(CattaneoMindlin, CattaneoMindlinStickZoneShrinksButFasterThanTheoryWhenDundursBetaIsLarge) {
  const double poisson = 0.3;
  const PartialSlipRun run = runPartialSlip(poisson);
  EXPECT_EQ(run.stick_count_increases, 0);
  double previous = 1.0;
  for (double target : kTargets) {
    const StickZone& z = nearest(run, target);
    print(poisson, z);
    ASSERT_NEAR(z.load_ratio, target, 0.01);
    EXPECT_LT(z.c_over_a, previous);
    EXPECT_LT(z.c_over_a, z.theory() - kStickZoneTolerance) << "Q/muP " << z.load_ratio;
    EXPECT_GT(z.c_over_a, 0.6 * z.theory()) << "Q/muP " << z.load_ratio;
    EXPECT_GT(std::abs(z.shift), 0.2) << "Q/muP " << z.load_ratio;
    previous = z.c_over_a;
  }
}

// Two identical elastic cylinders (node to node, tests/fixtures/two_bodies_scene.hpp) at ν = 0.3:
// β = 0, so Cattaneo–Mindlin is exact for the pair where it was off by 0.16–0.28 a for one body on
// the rigid flat (the test above). The stick zone's half-width c from the traction deficit must lie
// within one node spacing h of a √(1 − Q/μP) (h/a = 0.057 here), centred within h, and no
// node may return to stick under the monotone drive.
TEST(CattaneoMindlin, TwoIdenticalCylindersStickZoneMatchesTheoryWithinOneNodeSpacing) {
  const double poisson = 0.3;
  const PartialSlipRun run = runPartialSlip(poisson, true);
  EXPECT_EQ(run.stick_count_increases, 0);
  for (double target : kTargets) {
    const StickZone& z = nearest(run, target);
    print(poisson, z);
    std::cout << "[ measured ] pair: |c - c_theory| / h " << std::abs(z.c_over_a - z.theory()) * z.half_width / run.spacing
              << ", shift / h " << std::abs(z.shift) * z.half_width / run.spacing << "\n";
    ASSERT_NEAR(z.load_ratio, target, 0.01);
    EXPECT_LE(std::abs(z.c_over_a - z.theory()) * z.half_width, run.spacing) << "Q/muP " << z.load_ratio;
    EXPECT_LE(std::abs(z.shift) * z.half_width, run.spacing) << "Q/muP " << z.load_ratio;
  }
}

}  // namespace
}  // namespace stc::validation
