// The report's files from a hand-made comparison: well-formed markdown tables, "not reached" where
// a strategy stops short of a target, one CSV row per point and per strategy with the header's
// number of cells.
#include "stcontact/studies/comparison_writer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "studies/text_lines.hpp"

namespace stc {
namespace {

std::vector<WorkPoint> history(int iterations, double error_factor, double seconds_per_iteration) {
  std::vector<WorkPoint> points;
  for (int i = 1; i <= iterations; ++i)
    points.push_back({i, i, 10L * i, std::pow(error_factor, i), 0.5 * std::pow(error_factor, i), seconds_per_iteration * i});
  return points;
}

Comparison handMade() {
  Comparison c;
  c.scene_name = "toy";
  c.command = "stcontact compare toy.toml";
  c.repeats = 2;
  StrategyMeasurement latin, slow, exact;
  latin.solver = "latin";
  slow.solver = "slow";  // stops at 0.5·0.1^3 = 5e-4: never reaches 1e-4
  exact.solver = "incremental";
  exact.reference_point = true;
  for (int r = 1; r <= 2; ++r) {
    latin.runs.push_back({r, history(8, 0.1, 1.0), 8.0});
    slow.runs.push_back({r, history(3, 0.1, 2.0), 6.0});
    exact.runs.push_back({r, {{5, 0, 20, 1e-16, 0.0, 0.5}}, 0.5});
  }
  c.tolerance = 1e-6;
  latin.termination = Termination::Converged;
  latin.relaxations = 8;
  latin.sparse_solves = 80;
  latin.final_error_estimate = 9e-7;
  latin.final_error = 5e-9;
  slow.relaxations = 3;
  slow.final_error_estimate = std::numeric_limits<double>::infinity();  // never had an estimate
  exact.termination = Termination::Converged;
  c.strategies = {latin, slow, exact};
  return c;
}

int count(const std::string& text, char c) { return static_cast<int>(std::count(text.begin(), text.end(), c)); }

using test::lines;

TEST(SummaryMarkdown, EveryTableRowHasTheHeadersNumberOfCells) {
  const auto all = lines(summaryMarkdown(handMade()));
  int tables = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i].rfind("| strategy", 0) != 0) continue;
    ++tables;
    const int cells = count(all[i], '|');
    for (std::size_t j = i + 1; j < all.size() && !all[j].empty(); ++j)
      EXPECT_EQ(count(all[j], '|'), cells) << all[j];
  }
  EXPECT_EQ(tables, 5);
}

TEST(SummaryMarkdown, SaysNotReachedAndMarksTheReference) {
  const std::string md = summaryMarkdown(handMade());
  EXPECT_NE(md.find("| slow | 4 s | not reached | not reached |"), std::string::npos) << md;
  EXPECT_NE(md.find("incremental (reference)"), std::string::npos);
  EXPECT_NE(md.find("`stcontact compare toy.toml`"), std::string::npos);
}

// The first table is what `stcontact solve --tol` gives: the estimate each run stopped on, the true
// error at termination, the median of the whole calls (latin 8 s, incremental 0.5 s: ratio 16).
TEST(SummaryMarkdown, OpensWithTheSolveAtTheTolerance) {
  const std::string md = summaryMarkdown(handMade());
  const std::size_t tolerance = md.find("## A solve at tolerance 1e-06");
  ASSERT_NE(tolerance, std::string::npos) << md;
  EXPECT_LT(tolerance, md.find("## Time to first reach"));
  EXPECT_NE(md.find("| latin | converged | 8 | 80 | 9e-07 | 5e-09 | 8 s | 16 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| slow | max_iterations | 3 | 0 | none | unknown | 6 s | 12 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| incremental (reference) | converged | 0 | 0 | · | 0 (the reference) | 0.5 s | 1 |"),
            std::string::npos) << md;
}

TEST(WorkPrecisionCsv, HasOneRowPerPointOfEveryRun) {
  const auto all = lines(workPrecisionCsv(handMade()));
  EXPECT_EQ(all.size(), 1u + 2 * 8 + 2 * 3 + 2 * 1);
  for (const auto& line : all) EXPECT_EQ(count(line, ','), 7) << line;
}

TEST(SummaryCsv, HasOneRowPerStrategyWithTheHeadersCells) {
  const auto all = lines(summaryCsv(handMade()));
  ASSERT_EQ(all.size(), 4u);
  for (const auto& line : all) EXPECT_EQ(count(line, ','), count(all[0], ',')) << line;
  EXPECT_EQ(all[2].rfind("slow,2,", 0), 0u);
}

}  // namespace
}  // namespace stc
