// The coarse step's contact zone (fas/coarse_zone.hpp): the nodes it holds, and that eliminating the
// other nodes' rows keeps the fixed point of the restricted LATIN (fas/coarse_step.cpp).
#include <gtest/gtest.h>

#include <algorithm>

#include "fas/seed_fas_fixture.hpp"
#include "stcontact/fas/coarse_step.hpp"
#include "stcontact/fas/coarse_zone.hpp"
#include "stcontact/latin/global_stage.hpp"
#include "stcontact/latin/latin_solver.hpp"
#include "stcontact/latin/local_stage.hpp"

namespace {

// Four 2D nodes, k = 1, at three instants.
stc::ContactInterface fourNodes() {
  stc::ContactInterface c;
  c.nodes = {0, 1, 2, 3};
  c.initial_gap = Eigen::Vector4d(0.0, 0.5, 0.01, 2.0);
  c.search_direction = Eigen::VectorXd::Ones(8);
  return c;
}

}  // namespace

TEST(CoarseZone, HoldsTheClosedNodesAndThoseWithinTheIterationsReach) {
  const stc::ContactInterface contact = fourNodes();
  stc::InterfaceHistory hat = stc::InterfaceHistory::zeros(contact, 3);
  hat.v(0, 0) = -0.0;  // node 0 closed at instant 1 (v̂_n = −g0 = 0)
  hat.lambda(0, 1) = 0.2;
  stc::InterfaceHistory s = hat;
  // Converged (s = ŝ, δ = 0): only the closed node, although node 2's gap is 0.01.
  stc::fas::CoarseZone zone = stc::fas::coarseZone(contact, s, hat);
  EXPECT_EQ(zone.nodes, std::vector<int>({0}));
  EXPECT_EQ(zone.rows, std::vector<int>({0, 1}));
  EXPECT_EQ(zone.far_rows, std::vector<int>({2, 3, 4, 5, 6, 7}));
  // The iterates 0.1 apart on node 3's normal: δ = 0.1 takes node 2 (gap 0.01) in, not node 1 (0.5).
  s.v(6, 2) = hat.v(6, 2) + 0.1;
  zone = stc::fas::coarseZone(contact, s, hat);
  EXPECT_EQ(zone.nodes, std::vector<int>({0, 2}));
  EXPECT_EQ(zone.rows, std::vector<int>({0, 1, 4, 5}));
  EXPECT_EQ(zone.far_rows, std::vector<int>({2, 3, 6, 7}));
  // Tangential differences do not count.
  s.v(6, 2) = hat.v(6, 2);
  s.v(7, 0) = hat.v(7, 0) + 1.0;
  EXPECT_EQ(stc::fas::coarseZone(contact, s, hat).nodes, std::vector<int>({0}));
  EXPECT_EQ(stc::fas::wholeInterface(contact).nodes, std::vector<int>({0, 1, 2, 3}));
  EXPECT_TRUE(stc::fas::wholeInterface(contact).far_rows.empty());
}

namespace {

// The seed scene on 31 contact nodes × 41 instants, a LATIN iterate s some way from the solution (6
// iterations), and a coarse space of the solution's 30 leading displacement modes: more than the
// closed nodes (7) need, so that the restricted LATIN converges.
struct CoarseFixture {
  const stc::Problem& problem = stc::test::seedFas().problem;
  stc::fas::CoarseSpace space;
  stc::InterfaceHistory s;
  CoarseFixture() {
    stc::latin::GlobalStage global(problem);
    space = stc::fas::CoarseSpace(stc::test::seedFas().leadingModes(30), global.matrix(), problem.contact.B);
    stc::latin::LatinOptions latin;
    latin.stop.max_iterations = 6;
    latin.stop.tolerance = 1e-14;
    s = stc::latin::solveLatin(problem, latin).interface;
  }
  // The coarse step from s and its local stage on `contact`, i_C = `iterations`.
  stc::InterfaceHistory coarseStep(const stc::ContactInterface& contact, bool zone, int iterations) const {
    stc::InterfaceHistory hat;
    stc::latin::localStage(contact, s, hat);
    stc::fas::FasOptions options;
    options.coarse_zone = zone;
    options.coarse_iterations = iterations;
    stc::fas::coarseStep(contact, space, options, s, hat);
    return hat;
  }
};

const CoarseFixture& coarseFixture() {
  static const CoarseFixture f;
  return f;
}

double maxDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

}  // namespace

TEST(CoarseStep, WithoutContactOneEliminatedStageIsTheLimitOfTheRestrictedLatin) {
  // Every node 10 radii clear: the zone is empty and the restricted problem linear, solved by one
  // linear stage; the restricted LATIN over every node reaches it by iterating.
  const CoarseFixture& f = coarseFixture();
  stc::ContactInterface clear = f.problem.contact;
  clear.initial_gap.array() += 10.0;
  stc::InterfaceHistory hat;
  stc::latin::localStage(clear, f.s, hat);
  ASSERT_TRUE(stc::fas::coarseZone(clear, f.s, hat).nodes.empty());
  const stc::InterfaceHistory eliminated = f.coarseStep(clear, true, 1),
                              whole = f.coarseStep(clear, false, 100);
  const double force = f.s.lambda.cwiseAbs().maxCoeff(), motion = whole.v.cwiseAbs().maxCoeff();
  EXPECT_LE(maxDifference(eliminated.v, whole.v), 1e-12 * motion);  // measured: 5e-16
  EXPECT_LE(maxDifference(eliminated.lambda, whole.lambda), 1e-12 * force);
  EXPECT_GT(maxDifference(eliminated.v, f.coarseStep(clear, false, 1).v),
            1e-2 * motion);  // one plain stage is not it
}

TEST(CoarseStep, EliminatingTheFarRowsKeepsTheFixedPointOfTheRestrictedLatin) {
  // The nodes outside the zone lifted 10 radii clear, so that they are open in both forms at every
  // iteration; the closed ones kept. Both restricted LATINs converge (30 modes for 7 zone nodes),
  // to the same iterate.
  const CoarseFixture& f = coarseFixture();
  stc::InterfaceHistory hat;
  stc::latin::localStage(f.problem.contact, f.s, hat);
  const stc::fas::CoarseZone zone = stc::fas::coarseZone(f.problem.contact, f.s, hat);
  ASSERT_EQ(zone.nodes.size(), 7u);
  stc::ContactInterface lifted = f.problem.contact;
  for (int i = 0; i < lifted.size(); ++i)
    if (!std::binary_search(zone.nodes.begin(), zone.nodes.end(), i)) lifted.initial_gap[i] += 10.0;
  const stc::InterfaceHistory eliminated = f.coarseStep(lifted, true, 400),
                              whole = f.coarseStep(lifted, false, 400);
  const double force = whole.lambda.cwiseAbs().maxCoeff(), motion = whole.v.cwiseAbs().maxCoeff();
  // Measured: 1.9e-12 of the force and 2.5e-14 of the motion in Release, 5.5e-9 of the force with
  // the sanitizers (the Anderson-mixed iterations round differently and restart elsewhere); after
  // 10 iterations 1.5e-3 and 1e-4. 1e-6 is a thousand times below the unconverged difference.
  EXPECT_LE(maxDifference(eliminated.lambda, whole.lambda), 1e-6 * force);
  EXPECT_LE(maxDifference(eliminated.v, whole.v), 1e-6 * motion);
  // Far from converged the two differ (the far rows' iterates are not at their limit).
  EXPECT_GT(maxDifference(f.coarseStep(lifted, true, 10).lambda, f.coarseStep(lifted, false, 10).lambda),
            1e-4 * force);
}
