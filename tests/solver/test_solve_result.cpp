// A result whose contact-admissible iterate is held on a contact zone alone (SolveResult::
// admissible_nodes, as fas-apriori's zone rounds hand it): its states, its whole iterate and the
// one moved out are those of the iterate patched into the solution on the zone's rows.
#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#include "stcontact/solver/solve_result.hpp"

namespace {

constexpr int kNodes = 5, kSteps = 9, kDim = 3;

stc::ContactInterface interfaceOfFiveNodes() {
  stc::ContactInterface c;
  c.dimension = kDim;
  c.nodes = {10, 11, 12, 13, 14};
  c.friction = 0.3;
  return c;
}

// Open, sticking and slipping entries: λ_n of both signs, λ_t on and inside the cone, v_t moving or not.
stc::InterfaceHistory mixedHistory(int nodes, double force, unsigned seed) {
  std::srand(seed);
  stc::InterfaceHistory h{Eigen::MatrixXd::Random(kDim * nodes, kSteps), force * Eigen::MatrixXd::Random(kDim * nodes, kSteps)};
  for (int i = 0; i < nodes; ++i)
    for (int k = 0; k < kSteps; ++k) {
      if ((i + k) % 3 == 0) h.v.block(kDim * i + 1, k, 2, 1) = k > 0 ? h.v.block(kDim * i + 1, k - 1, 2, 1).eval()
                                                                      : Eigen::MatrixXd::Zero(2, 1);
      if ((i + k) % 2 == 0) {  // on the cone: |λ_t| = μ λ_n
        h.lambda(kDim * i, k) = std::abs(h.lambda(kDim * i, k));
        h.lambda.block(kDim * i + 1, k, 2, 1) *= 0.3 * h.lambda(kDim * i, k) / h.lambda.block(kDim * i + 1, k, 2, 1).norm();
      }
    }
  return h;
}

// A result as zone rounds leave it: the solution on every node, the admissible iterate on nodes 1
// and 3, its forces ten times the solution's. The solution's rows of the zone are a thousand times
// larger, so that a scale read from them shows.
stc::SolveResult zoneResult() {
  stc::SolveResult r;
  r.interface = mixedHistory(kNodes, 1.0, 7);
  r.admissible_nodes = {1, 3};
  r.contact_admissible = mixedHistory(2, 10.0, 11);
  for (int node : r.admissible_nodes) r.interface.lambda.middleRows(kDim * node, kDim) *= 1e3;
  // Closed at the patched iterate's force scale (≤ 10: λ_n > 1e-10 · 10), open at one of 1e3 or more.
  r.interface.lambda(0, 1) = 1e-8;
  return r;
}

}  // namespace

TEST(SolveResult, AdmissibleOnAZoneIsTheSolutionPatchedOnItsRows) {
  const stc::SolveResult r = zoneResult();
  const stc::InterfaceHistory all = r.admissible();
  for (int i = 0; i < kNodes; ++i) {
    const int j = i == 1 ? 0 : i == 3 ? 1 : -1;
    const stc::InterfaceHistory& from = j >= 0 ? *r.contact_admissible : r.interface;
    const int row = kDim * (j >= 0 ? j : i);
    EXPECT_EQ(all.v.middleRows(kDim * i, kDim), from.v.middleRows(row, kDim)) << i;
    EXPECT_EQ(all.lambda.middleRows(kDim * i, kDim), from.lambda.middleRows(row, kDim)) << i;
  }
  stc::SolveResult moved = zoneResult();
  const stc::InterfaceHistory taken = std::move(moved).takeAdmissible();
  EXPECT_EQ(taken.v, all.v);
  EXPECT_EQ(taken.lambda, all.lambda);
}

TEST(SolveResult, StatesOnAZoneAreThoseOfThePatchedIterate) {
  const stc::ContactInterface contact = interfaceOfFiveNodes();
  const stc::SolveResult r = zoneResult();
  const stc::InterfaceHistory all = r.admissible();
  const stc::ContactStateTable patched = r.contactStates(contact), expected(contact, all), of_solution(contact, r.interface);
  int differ_from_solution = 0;
  for (int i = 0; i < kNodes; ++i)
    for (int k = 0; k < kSteps; ++k) {
      EXPECT_EQ(patched.state(i, k), expected.state(i, k)) << i << " " << k;
      EXPECT_EQ(patched.slip(i, k), expected.slip(i, k)) << i << " " << k;
      differ_from_solution += patched.state(i, k) != of_solution.state(i, k);
    }
  EXPECT_GT(differ_from_solution, 0);  // the check above can tell the zone's iterate from the solution
  // The scale is the patched iterate's, not the solution's on the zone's rows.
  EXPECT_NE(patched.state(0, 1), stc::ContactState::Open);
  EXPECT_EQ(of_solution.state(0, 1), stc::ContactState::Open);
}

TEST(SolveResult, StatesWithoutAnAdmissibleIterateAreTheSolutions) {
  const stc::ContactInterface contact = interfaceOfFiveNodes();
  stc::SolveResult r;
  r.interface = mixedHistory(kNodes, 1.0, 5);
  const stc::ContactStateTable states = r.contactStates(contact), expected(contact, r.interface);
  for (int i = 0; i < kNodes; ++i)
    for (int k = 0; k < kSteps; ++k) EXPECT_EQ(states.state(i, k), expected.state(i, k));
}
