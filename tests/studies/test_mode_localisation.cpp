// Localisation of spatial modes at the contact zone (studies/mode_localisation.hpp): the element
// energies add up to ΥᵀKΥ, rigid motions carry none, a uniform strain spreads its energy like the
// area, a field living on the contact zone is fully inside the band, the seed's contact zone is the
// closed arc segment, and the seed's observation (§3.2) that the higher modes localise at the contact.
#include <gtest/gtest.h>

#include <random>

#include "fixtures/seed_scene.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/linalg/backends/cholmod_factor.hpp"
#include "stcontact/operators/displacement.hpp"
#include "stcontact/pgd/space_time_svd.hpp"
#include "stcontact/studies/mode_localisation.hpp"

namespace {

using stc::ContactZone;
using stc::ModeLocalisation;

struct Solved {
  stc::Problem problem;
  stc::SolveResult result;
};

// The seed scene (docs/method.md §6) solved once by the incremental solver.
const Solved& seed() {
  static const Solved solved = [] {
    Solved s{stc::buildProblem(stc::test::seedScene()), {}};
    s.result = stc::solveIncremental(s.problem);
    return s;
  }();
  return solved;
}

ModeLocalisation seedLocalisation() {
  const Solved& s = seed();
  return ModeLocalisation(s.problem, ContactZone::everClosed(s.problem, s.result), {0.05, 0.1, 0.2});
}

Eigen::VectorXd randomField(int n, unsigned seed_value) {
  std::mt19937 engine(seed_value);
  std::normal_distribution<double> normal;
  Eigen::VectorXd u(n);
  for (int i = 0; i < n; ++i) u[i] = normal(engine);
  return u;
}

// u(x) = a + ω × x + E x at every node (2D: rotation ω, constant strain E).
Eigen::VectorXd affineField(const stc::TriMesh& mesh, const Eigen::Vector2d& a, double omega, const Eigen::Matrix2d& E) {
  Eigen::VectorXd u(mesh.numDofs());
  for (int j = 0; j < mesh.numNodes(); ++j) {
    const Eigen::Vector2d x = mesh.nodes.col(j);
    u.segment<2>(2 * j) = a + omega * Eigen::Vector2d(-x.y(), x.x()) + E * x;
  }
  return u;
}

TEST(ModeLocalisation, ElementEnergiesAddUpToTheStiffnessQuadraticForm) {
  const ModeLocalisation loc = seedLocalisation();
  const auto& K = seed().problem.stiffness;
  const Eigen::VectorXd u = randomField(static_cast<int>(K.rows()), 7);
  const double expected = u.dot(K * u);
  EXPECT_NEAR(loc.elementEnergies(u).sum(), expected, 1e-12 * expected);
  EXPECT_NEAR(loc.measure(u).energy, expected, 1e-12 * expected);
}

TEST(ModeLocalisation, RigidMotionCarriesNoEnergy) {
  const ModeLocalisation loc = seedLocalisation();
  const auto& mesh = std::get<stc::TriMesh>(seed().problem.body);
  const Eigen::VectorXd rigid = affineField(mesh, {0.3, -0.2}, 0.1, Eigen::Matrix2d::Zero());
  const Eigen::VectorXd strained = affineField(mesh, {0.0, 0.0}, 0.0, Eigen::Matrix2d::Identity() * 0.1);
  EXPECT_LT(loc.elementEnergies(rigid).cwiseAbs().maxCoeff(), 1e-14 * loc.elementEnergies(strained).sum());
}

TEST(ModeLocalisation, UniformStrainSpreadsItsEnergyLikeTheArea) {
  const ModeLocalisation loc = seedLocalisation();
  Eigen::Matrix2d E;
  E << 0.01, 0.004, 0.004, -0.02;
  const auto m = loc.measure(affineField(std::get<stc::TriMesh>(seed().problem.body), {0.1, 0.0}, 0.05, E));
  const std::vector<double> area_share = loc.bandAreaShares();
  for (std::size_t j = 0; j < area_share.size(); ++j) EXPECT_NEAR(m.band_share[j], area_share[j], 1e-12);
  const double mean_distance = loc.areas().dot(loc.distances()) / loc.areas().sum();
  EXPECT_NEAR(m.mean_distance, mean_distance, 1e-12);
  EXPECT_LT(area_share[0], area_share[1]);
  EXPECT_LT(area_share[1], area_share[2]);
}

TEST(ModeLocalisation, FieldLivingOnTheContactZoneIsInsideTheNarrowestBand) {
  const ModeLocalisation loc = seedLocalisation();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(seed().problem.numDofs());
  for (int node : loc.zone().nodes) u[2 * node + 1] = 1e-3 * (node % 3 - 1.0);
  const auto m = loc.measure(u);
  EXPECT_GT(m.energy, 0.0);
  EXPECT_NEAR(m.band_share[0], 1.0, 1e-15);
  EXPECT_LT(m.mean_distance, 0.03);  // below one element size at the arc
}

TEST(ModeLocalisation, SeedContactZoneIsTheClosedArcSegment) {
  const ModeLocalisation loc = seedLocalisation();
  const ContactZone& zone = loc.zone();
  const auto& mesh = std::get<stc::TriMesh>(seed().problem.body);
  // 21 nodes at t_200 (reactions.csv of the same solve: n_contact = 21, x in [−0.303, 0.303]).
  EXPECT_EQ(zone.nodes.size(), 21u);
  EXPECT_EQ(zone.edges.size(), zone.nodes.size() - 1);  // one connected arc segment
  EXPECT_NEAR(zone.xmin, -0.303, 1e-3);
  EXPECT_NEAR(zone.xmax, 0.303, 1e-3);
  for (int node : zone.nodes) EXPECT_NEAR(mesh.nodes.col(node).norm(), 1.0, 1e-12);
  EXPECT_EQ(loc.distances().size(), mesh.numElements());
  EXPECT_GE(loc.distances().minCoeff(), 0.0);
}

// Seed §3.2: "the first space modes are global, the higher ones localised at the contact zone".
// As numbers (docs/svd_seed.md): the energy-weighted distance to the zone shrinks mode after mode,
// from about 0.4 R to below the arc's element size, and the share within 0.1 R grows.
TEST(ModeLocalisation, SeedHigherModesLocaliseAtTheContact) {
  const Solved& s = seed();
  const stc::CholmodFactor factor(s.problem.stiffness_free, "K_ff");
  const Eigen::MatrixXd U = stc::fullDisplacements(s.problem, factor, s.result.interface.lambda);
  const stc::pgd::SpaceTimeSvd svd = stc::pgd::energySvd(U, s.problem.stiffness, {stc::pgd::SvdMethod::Dense, 10});
  const ModeLocalisation loc = seedLocalisation();
  double previous_distance = 1.0, first_share = 0.0;
  for (int i = 0; i < 6; ++i) {
    const auto m = loc.measure(svd.space.col(i));
    EXPECT_NEAR(m.energy, 1.0, 1e-10) << "mode " << i + 1;  // energy-orthonormal modes
    EXPECT_LT(m.mean_distance, previous_distance) << "mode " << i + 1;
    previous_distance = m.mean_distance;
    if (i == 0) first_share = m.band_share[1];
    if (i >= 3) EXPECT_GT(m.band_share[1], 0.9) << "mode " << i + 1;
  }
  EXPECT_LT(first_share, 0.3);
  EXPECT_LT(previous_distance, M_PI / 102.0);  // mode 6: closer than one arc element size
}

TEST(ModeLocalisation, EmptyZoneAndBadDepthsAreInputErrors) {
  const Solved& s = seed();
  EXPECT_THROW(ModeLocalisation(s.problem, ContactZone{}, {0.1}), stc::InputError);
  const ContactZone zone = ContactZone::everClosed(s.problem, s.result);
  EXPECT_THROW(ModeLocalisation(s.problem, zone, {0.0}), stc::InputError);
  EXPECT_THROW(ModeLocalisation(s.problem, zone, {-1.0}), stc::InputError);
  const ModeLocalisation loc(s.problem, zone, {0.1});
  EXPECT_THROW(loc.measure(Eigen::VectorXd::Zero(5)), stc::InputError);
}

TEST(ModeLocalisation, NoContactMeansNoZone) {
  stc::Scene scene = stc::test::seedScene(21, 21);
  scene.dirichlet[1].history.values = {0.0, 0.0, 0.0};  // the body never reaches the foundation
  const stc::Problem problem = stc::buildProblem(scene);
  const stc::SolveResult result = stc::solveIncremental(problem);
  EXPECT_TRUE(ContactZone::everClosed(problem, result).empty());
}

}  // namespace
