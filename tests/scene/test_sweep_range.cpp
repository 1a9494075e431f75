// `--set-range KEY=FROM:TO:COUNT` (src/scene/sweep_range.hpp): evenly spaced values, both ends
// included, written so that the scene reader reads back what is solved; malformed ranges refused.
#include <gtest/gtest.h>

#include "stcontact/core/input_error.hpp"
#include "stcontact/scene/sweep_range.hpp"

TEST(SweepRange, EvenlySpacedValuesWithBothEnds) {
  const stc::SweepRange r = stc::parseSweepRange("contact.friction=0.05:0.5:10");
  EXPECT_EQ(r.key, "contact.friction");
  ASSERT_EQ(r.values.size(), 10u);
  const std::vector<std::string> expected = {"0.05", "0.1", "0.15", "0.2", "0.25", "0.3", "0.35", "0.4", "0.45", "0.5"};
  EXPECT_EQ(r.texts, expected);
  for (std::size_t i = 0; i < r.values.size(); ++i) EXPECT_DOUBLE_EQ(r.values[i], 0.05 + 0.05 * i);
  EXPECT_EQ(r.override(2), "contact.friction=0.15");
}

TEST(SweepRange, DescendingIntegerAndSingleValues) {
  const stc::SweepRange down = stc::parseSweepRange(" material.young = 4000 : 2000 : 3 ");
  EXPECT_EQ(down.key, "material.young");
  EXPECT_EQ(down.texts, (std::vector<std::string>{"4000", "3000", "2000"}));  // integers stay integers
  const stc::SweepRange one = stc::parseSweepRange("mesh.arc_nodes=21:21:1");
  EXPECT_EQ(one.texts, std::vector<std::string>{"21"});
}

TEST(SweepRange, RefusesWhatIsNotKeyFromToCount) {
  for (const char* bad : {"contact.friction", "contact.friction=0.05:0.5", "contact.friction=0.05:0.5:10:2",
                          "=0.05:0.5:10", "contact.friction=a:0.5:10", "contact.friction=0.05:nan:10",
                          "contact.friction=0.05:inf:10", "contact.friction=0.05:0.5:0", "contact.friction=0.05:0.5:-3",
                          "contact.friction=0.05:0.5:2.5", "contact.friction=0.05:0.5:1",
                          "contact.friction=0.05:0.5:100000", "contact.friction=1:1.0000000000001:5"})
    EXPECT_THROW(stc::parseSweepRange(bad), stc::InputError) << bad;
}

TEST(SweepRange, MessageNamesTheRangeAndTheRule) {
  try {
    stc::parseSweepRange("contact.friction=0.05:0.5:0");
    FAIL() << "accepted COUNT = 0";
  } catch (const stc::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--set-range 'contact.friction=0.05:0.5:0'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("COUNT"), std::string::npos) << e.what();
  }
}
