// The problem on some of its instants (src/problem/time_subgrid.hpp): the instants every q-th, and a
// sub-problem whose loads at its instants are the whole problem's at the same times, against the
// scene sampled on the coarser grid directly.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "fixtures/seed_scene.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/problem/time_subgrid.hpp"

TEST(TimeSubgrid, EveryNthInstantKeepsTheFirstAndTheLast) {
  EXPECT_EQ(stc::everyNthInstant(9, 4), (std::vector<int>{0, 4, 8}));
  EXPECT_EQ(stc::everyNthInstant(10, 4), (std::vector<int>{0, 4, 8, 9}));
  EXPECT_EQ(stc::everyNthInstant(1, 3), (std::vector<int>{0}));
  const std::vector<int> kept = stc::everyNthInstant(2001, 10);
  ASSERT_EQ(kept.size(), 201u);
  EXPECT_EQ(kept.back(), 2000);
  EXPECT_THROW(stc::everyNthInstant(0, 2), std::invalid_argument);
  EXPECT_THROW(stc::everyNthInstant(5, 0), std::invalid_argument);
}

// The seed scene on 41 instants, every 4th kept: the scene on 11 instants of the same interval has
// the same times and the same loads (the histories are piecewise linear with a kink at t = 0.2, an
// instant of both grids).
TEST(TimeSubgrid, OnInstantsIsTheSceneOnTheCoarserGrid) {
  const stc::Problem whole = stc::buildProblem(stc::test::seedScene(21, 41));
  const stc::Problem coarse = stc::buildProblem(stc::test::seedScene(21, 11));
  const stc::Problem sub = stc::onInstants(whole, stc::everyNthInstant(41, 4));
  ASSERT_EQ(sub.numSteps(), 11);
  for (int k = 0; k < 11; ++k) {
    EXPECT_NEAR(sub.times[static_cast<size_t>(k)], coarse.times[static_cast<size_t>(k)], 1e-15);
    EXPECT_LE((sub.load(k) - coarse.load(k)).norm(), 1e-12 * coarse.load(k).norm()) << "instant " << k;
    EXPECT_EQ(sub.load(k), whole.load(4 * k));
  }
  // Nothing but the grid changes.
  EXPECT_EQ(sub.contact.size(), whole.contact.size());
  EXPECT_EQ(sub.numFreeDofs(), whole.numFreeDofs());
  EXPECT_EQ(sub.loads.size(), whole.loads.size());
}

TEST(TimeSubgrid, RefusesInstantsThatDoNotIncreaseWithinTheGrid) {
  const stc::Problem p = stc::buildProblem(stc::test::seedScene(21, 11));
  EXPECT_THROW(stc::onInstants(p, {}), std::invalid_argument);
  EXPECT_THROW(stc::onInstants(p, {0, 5, 5}), std::invalid_argument);
  EXPECT_THROW(stc::onInstants(p, {0, 4, 2}), std::invalid_argument);
  EXPECT_THROW(stc::onInstants(p, {0, 11}), std::invalid_argument);
  EXPECT_THROW(stc::onInstants(p, {-1, 3}), std::invalid_argument);
}
