// A phase of a solve outside its iterations (src/solver/noted_phase.hpp): the lines it tells through
// SolveInputs::phase_note when it starts, while it runs (at most once per interval) and when it ends.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "stcontact/solver/noted_phase.hpp"

namespace {

struct Lines {
  std::vector<std::string> told;
  stc::PhaseNote note() {
    return [this](const std::string& line) { told.push_back(line); };
  }
};

bool startsWith(const std::string& text, const std::string& start) { return text.rfind(start, 0) == 0; }

}  // namespace

TEST(NotedPhase, TellsItsStartAndItsSolvesAndSecondsAtTheEnd) {
  Lines lines;
  const stc::NotedPhase phase(lines.note(), "before the march: ");
  phase.begin("the Delassus columns of the 2 nodes within reach, 6 sparse solves");
  phase.end(6);
  ASSERT_EQ(lines.told.size(), 2u);
  EXPECT_EQ(lines.told[0], "before the march: the Delassus columns of the 2 nodes within reach, 6 sparse solves");
  EXPECT_TRUE(startsWith(lines.told[1], "before the march: 6 sparse solves, ")) << lines.told[1];
  EXPECT_EQ(lines.told[1].substr(lines.told[1].size() - 2), " s");
}

TEST(NotedPhase, EndsSilentlyWhenNothingWasSolved) {
  Lines lines;
  stc::NotedPhase(lines.note(), "after the last iteration: ").end(0);
  EXPECT_TRUE(lines.told.empty());
}

// With no interval every call tells where the phase is, with its seconds since the start.
TEST(NotedPhase, TellsWhereItIsEveryIntervalWhileItRuns) {
  Lines lines;
  stc::NotedPhase phase(lines.note(), "before the march: ", 0.0);
  phase.during("1 of 3 nodes, 3 sparse solves");
  phase.during("2 of 3 nodes, 6 sparse solves");
  ASSERT_EQ(lines.told.size(), 2u);
  EXPECT_TRUE(startsWith(lines.told[0], "before the march: 1 of 3 nodes, 3 sparse solves, ")) << lines.told[0];
  EXPECT_TRUE(startsWith(lines.told[1], "before the march: 2 of 3 nodes, 6 sparse solves, ")) << lines.told[1];
}

// Within the interval (an hour here, a minute by default) it tells nothing: a phase of many short
// chunks does not fill the log.
TEST(NotedPhase, TellsNothingWhileRunningWithinTheInterval) {
  Lines lines;
  stc::NotedPhase phase(lines.note(), "before the march: ", 3600.0);
  for (int k = 0; k < 100; ++k) phase.during("a chunk");
  EXPECT_TRUE(lines.told.empty());
  stc::NotedPhase by_default(lines.note(), "before the march: ");
  by_default.during("a chunk");
  EXPECT_TRUE(lines.told.empty()) << "the default interval is a minute";
}
