// A caller's stop (src/core/interruption.hpp): while a StopProbe lives, keepGoing() on its thread asks
// it and stopPoint() throws Interrupted once it answers false; scopes nest, and other threads do not
// see another thread's probe.
#include "stcontact/core/interruption.hpp"

#include <gtest/gtest.h>

#include <thread>

TEST(StopProbe, AnswersForItsThreadWhileItLives) {
  EXPECT_TRUE(stc::keepGoing());
  EXPECT_NO_THROW(stc::stopPoint());
  {
    const stc::StopProbe probe([] { return false; });
    EXPECT_FALSE(stc::keepGoing());
    EXPECT_THROW(stc::stopPoint(), stc::Interrupted);
    bool elsewhere = false;
    std::thread other([&] { elsewhere = stc::keepGoing(); });
    other.join();
    EXPECT_TRUE(elsewhere);  // another thread's solve is not stopped
  }
  EXPECT_TRUE(stc::keepGoing());
}

TEST(StopProbe, ScopesNest) {
  const stc::StopProbe outer([] { return false; });
  {
    const stc::StopProbe inner([] { return true; });
    EXPECT_TRUE(stc::keepGoing());
  }
  EXPECT_FALSE(stc::keepGoing());  // the outer one is back
}

TEST(StopProbe, ARequestedStopHoldsWhateverTheProbeSays) {
  const stc::StopProbe probe([] { return true; });
  stc::requestInterruption(0);
  EXPECT_FALSE(stc::keepGoing());
  EXPECT_THROW(stc::stopPoint(), stc::Interrupted);
  stc::clearInterruption();
  EXPECT_TRUE(stc::keepGoing());
}
