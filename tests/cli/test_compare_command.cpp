// `stcontact compare` end to end on the seed scene at small settings (21 contact nodes, 21 instants,
// 2 repeats): exit status, the documented columns, a row for every available strategy, and summary
// numbers that are the medians of what work_precision.csv records. No wall-clock value is asserted,
// only relations between the files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/csv_table.hpp"
#include "cli/run_program.hpp"
#include "stcontact/strategies/registry.hpp"
#include "stcontact/studies/comparison.hpp"
#include "stcontact/studies/number_format.hpp"
#include "stcontact/studies/work_precision.hpp"

namespace stc {
namespace {

namespace fs = std::filesystem;

using Table = test::CsvTable;
using test::number;
using test::readCsv;

class CompareCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    out_ = test::scratchFolder("compare_small");
    exit_status_ = test::runOnSmallSeed("compare", "--repeats 2", out_);
    work_ = readCsv(out_ / "report" / "work_precision.csv");
    summary_ = readCsv(out_ / "report" / "summary.csv");
  }
  static void TearDownTestSuite() {
    std::error_code ignored;
    fs::remove_all(out_, ignored);
  }

  /// The timed runs of `solver` as the report's statistics see them, read back from the CSV.
  static std::vector<TimedRun> runsOf(const std::string& solver) {
    std::map<int, TimedRun> runs;
    for (const auto& row : work_.rows) {
      if (row.at("solver") != solver) continue;
      const int repeat = std::stoi(row.at("repeat"));
      TimedRun& run = runs[repeat];
      run.repeat = repeat;
      run.points.push_back({std::stoi(row.at("iteration")), std::stoi(row.at("relaxations")),
                            std::stol(row.at("sparse_solves")), std::stod(row.at("indicator")),
                            number(row.at("error")), std::stod(row.at("wall_s"))});
    }
    std::vector<TimedRun> out;
    for (auto& [repeat, run] : runs) out.push_back(run);
    return out;
  }

  static const std::map<std::string, std::string>* summaryRow(const std::string& solver) {
    for (const auto& row : summary_.rows)
      if (row.at("solver") == solver) return &row;
    return nullptr;
  }

  static inline fs::path out_;
  static inline int exit_status_ = -1;
  static inline Table work_, summary_;
};

TEST_F(CompareCommand, ExitsZeroAndWritesTheCsvAndSummaryFiles) {
  EXPECT_EQ(exit_status_, 0);
  for (const char* name : {"work_precision.csv", "summary.csv", "summary.md"})
    EXPECT_GT(fs::file_size(out_ / "report" / name), 0u) << name;
}

TEST_F(CompareCommand, WorkPrecisionCsvHasTheDocumentedColumns) {
  const std::vector<std::string> expected = {"solver",    "repeat", "iteration", "relaxations",
                                             "sparse_solves", "indicator", "error", "wall_s"};
  EXPECT_EQ(work_.header, expected);
  for (const auto& row : work_.rows) EXPECT_EQ(row.size(), expected.size());
}

TEST_F(CompareCommand, SummaryCsvHasOneColumnPerTargetAndRatio) {
  for (double t : targetErrors()) {
    const std::string l = targetLabel(t);
    for (const std::string& column : {"time_to_" + l + "_s", "relaxations_to_" + l, "sparse_solves_to_" + l,
                                      "time_ratio_to_latin_" + l, "time_ratio_to_incremental_" + l})
      EXPECT_NE(std::find(summary_.header.begin(), summary_.header.end(), column), summary_.header.end()) << column;
  }
  for (const char* column : {"solver", "termination", "final_error", "peak_rss_mb", "rss_growth_mb"})
    EXPECT_NE(std::find(summary_.header.begin(), summary_.header.end(), column), summary_.header.end()) << column;
}

TEST_F(CompareCommand, EveryAvailableStrategyHasASummaryRowAndBothRepeats) {
  for (const std::string& solver : stc::strategyNames()) {
    ASSERT_NE(summaryRow(solver), nullptr) << solver;
    EXPECT_EQ(summaryRow(solver)->at("repeats"), "2") << solver;
    const auto runs = runsOf(solver);
    ASSERT_EQ(runs.size(), 2u) << solver;
    EXPECT_FALSE(runs[0].points.empty()) << solver;
  }
  EXPECT_EQ(summary_.rows.size(), stc::strategyNames().size());
}

TEST_F(CompareCommand, SummaryTimesAreMediansOverRepeatsOfTheFirstReach) {
  for (const std::string& solver : stc::strategyNames()) {
    const auto* row = summaryRow(solver);
    ASSERT_NE(row, nullptr) << solver;
    const auto runs = runsOf(solver);
    for (double t : targetErrors()) {
      const Reach expected = reachOf(runs, t);
      const std::string l = targetLabel(t);
      const auto time = number(row->at("time_to_" + l + "_s"));
      ASSERT_EQ(time.has_value(), expected.wall_s.has_value()) << solver << " " << l;
      if (!time) continue;
      EXPECT_NEAR(*time, *expected.wall_s, 1e-3 * *expected.wall_s) << solver << " " << l;  // 4 digits printed
      EXPECT_EQ(*number(row->at("relaxations_to_" + l)), *expected.relaxations) << solver << " " << l;
      EXPECT_EQ(*number(row->at("sparse_solves_to_" + l)), *expected.sparse_solves) << solver << " " << l;
    }
  }
}

TEST_F(CompareCommand, ErrorsOfTimedRunsEndAtTheReportedFinalError) {
  for (const std::string& solver : stc::strategyNames()) {
    const auto final_error = number(summaryRow(solver)->at("final_error"));
    ASSERT_TRUE(final_error.has_value()) << solver;
    for (const TimedRun& run : runsOf(solver)) {
      ASSERT_TRUE(run.points.back().error.has_value()) << solver;
      EXPECT_NEAR(*run.points.back().error, *final_error, 1e-3 * *final_error + 1e-300) << solver;
    }
  }
}

TEST_F(CompareCommand, IncrementalIsOneExactPointPerRepeatAndTheRatioBase) {
  const auto runs = runsOf("incremental");
  ASSERT_EQ(runs.size(), 2u);
  for (const TimedRun& run : runs) {
    ASSERT_EQ(run.points.size(), 1u);
    EXPECT_EQ(run.points[0].relaxations, 0);
    EXPECT_EQ(*run.points[0].error, 0.0);
  }
  for (double t : targetErrors()) EXPECT_EQ(summaryRow("incremental")->at("time_ratio_to_incremental_" + targetLabel(t)), "1");
  EXPECT_EQ(summaryRow("latin")->at("time_ratio_to_latin_1e-2"), "1");
}

TEST_F(CompareCommand, DrawsThePlotsOrSaysHowToDrawThemLater) {
  std::ifstream err(out_ / "stderr.txt");
  const std::string text((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  if (text.find("warning: gnuplot") != std::string::npos) {
    EXPECT_NE(text.find("draw them later"), std::string::npos);
    return;
  }
  for (const char* name : {"error_vs_time.png", "error_vs_relaxations.png", "error_vs_sparse_solves.png"})
    EXPECT_GT(fs::file_size(out_ / "report" / name), 0u) << name;
}

}  // namespace
}  // namespace stc
