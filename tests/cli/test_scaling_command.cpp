// `stcontact scaling` end to end on the seed scene at tiny settings (mesh series 11, 21 arc nodes at
// 21 instants; time series 11, 21 instants at 21 arc nodes; one repeat): exit status, the files,
// every row reaching the target or saying why not, runs stopped at the first iteration that reaches
// it, and growth exponents in the report that are the fits of the CSV's times. No wall-clock value
// is asserted, only relations between the files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "cli/csv_table.hpp"
#include "cli/run_program.hpp"
#include "stcontact/strategies/registry.hpp"
#include "stcontact/studies/growth_fit.hpp"

namespace stc {
namespace {

namespace fs = std::filesystem;
using test::number;
using test::readCsv;
using test::readText;
using Table = test::CsvTable;

constexpr double kTarget = 1e-4;

/// One `stcontact scaling` run on the small seed and what it wrote, removed with the suite.
struct ScalingReport {
  fs::path out;
  int exit_status = -1;
  Table rows;
  std::string summary;

  void run(const std::string& name, const std::string& options) {
    out = test::scratchFolder(name);
    exit_status = test::runOnSmallSeed("scaling", options, out);
    rows = readCsv(out / "report" / "scaling.csv");
    summary = readText(out / "report" / "summary.md");
  }
  void remove() const {
    std::error_code ignored;
    fs::remove_all(out, ignored);
  }
};

class ScalingCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    report_.run("scaling_tiny", "--arc-nodes 11,21 --steps 11,21 --repeats 1");
  }
  static void TearDownTestSuite() { report_.remove(); }

  /// (size, time to the target) of `solver` in `series` where it was reached.
  static std::vector<std::pair<double, double>> reached(const std::string& solver, const std::string& series) {
    std::vector<std::pair<double, double>> out;
    for (const auto& row : report_.rows.rows)
      if (row.at("solver") == solver && row.at("series") == series && row.at("status") == "reached")
        out.emplace_back(std::stod(row.at(series == "mesh" ? "dofs" : "steps")), std::stod(row.at("time_to_target_s")));
    return out;
  }

  static inline ScalingReport report_;
};

TEST_F(ScalingCommand, ExitsZeroAndWritesTheReportAndOneComparisonPerSize) {
  EXPECT_EQ(report_.exit_status, 0);
  for (const char* name : {"scaling.csv", "summary.md"}) EXPECT_GT(fs::file_size(report_.out / "report" / name), 0u) << name;
  // (11, 21) and (21, 21) from the mesh series, (21, 11) from the time series; (21, 21) is in both.
  for (const char* size : {"arc_nodes_11_steps_21", "arc_nodes_21_steps_21", "arc_nodes_21_steps_11"})
    for (const char* name : {"work_precision.csv", "summary.csv", "summary.md"})
      EXPECT_TRUE(fs::exists(report_.out / "report" / "sizes" / size / name)) << size << "/" << name;
}

TEST_F(ScalingCommand, HasOneRowPerSeriesSizeAndStrategy) {
  const std::size_t solvers = stc::strategyNames().size();
  EXPECT_EQ(report_.rows.rows.size(), 4 * solvers);
  for (const char* column : {"series", "arc_nodes", "dofs", "contact_nodes", "steps", "solver", "status",
                             "time_to_target_s", "relaxations_to_target", "sparse_solves_to_target", "peak_rss_mb"})
    EXPECT_NE(std::find(report_.rows.header.begin(), report_.rows.header.end(), column), report_.rows.header.end()) << column;
}

TEST_F(ScalingCommand, EveryRowHasATimeOrSaysWhyNot) {
  for (const auto& row : report_.rows.rows) {
    const auto time = number(row.at("time_to_target_s"));
    if (row.at("status") == "reached") {
      ASSERT_TRUE(time.has_value()) << row.at("solver");
      EXPECT_GT(*time, 0.0) << row.at("solver");
    } else {
      EXPECT_FALSE(time.has_value()) << row.at("solver");
      EXPECT_FALSE(row.at("status").empty());
    }
  }
}

// The early stop: every timed run of an iterative strategy ends at its first point at or below the target.
TEST_F(ScalingCommand, IterativeRunsStopAtTheFirstIterationReachingTheTarget) {
  for (const auto& size : fs::directory_iterator(report_.out / "report" / "sizes")) {
    std::map<std::string, std::vector<double>> errors;
    for (const auto& row : readCsv(size.path() / "work_precision.csv").rows)
      if (row.at("solver") != "incremental") errors[row.at("solver")].push_back(number(row.at("error")).value_or(NAN));
    for (const auto& [solver, e] : errors) {
      ASSERT_FALSE(e.empty());
      EXPECT_LE(e.back(), kTarget) << size.path().filename() << " " << solver;
      for (std::size_t i = 0; i + 1 < e.size(); ++i) EXPECT_GT(e[i], kTarget) << solver << " point " << i;
    }
  }
}

/// The cells of a markdown table row "| a | b | c |": {"a", "b", "c"}.
std::vector<std::string> cellsOf(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = line.find('|');
  while (start != std::string::npos) {
    const std::size_t end = line.find('|', start + 1);
    if (end == std::string::npos) break;
    cells.push_back(line.substr(start + 1, end - start - 1));
    start = end;
  }
  return cells;
}

using SizeTimes = std::vector<std::pair<double, double>>;

/// Checks that the report's growth exponents are the fits of `points(solver, series)`.
template <typename Points>
void expectExponentsFitted(const std::string& summary, Points points_of) {
  for (const std::string& solver : stc::strategyNames()) {
    const auto at = summary.find("| " + solver + " |", summary.find("## Growth exponents"));
    ASSERT_NE(at, std::string::npos) << solver;
    const auto cells = cellsOf(summary.substr(at, summary.find('\n', at) - at));
    ASSERT_EQ(cells.size(), 3u) << solver;
    for (int k : {1, 2}) {
      const SizeTimes points = points_of(solver, k == 1 ? "mesh" : "time");
      if (points.size() < 2) continue;
      std::vector<double> sizes, times;
      for (const auto& [size, time] : points) {
        sizes.push_back(size);
        times.push_back(time);
      }
      const PowerLawFit fit = fitPowerLaw(sizes, times);
      ASSERT_TRUE(std::isfinite(fit.exponent)) << solver;
      // The report prints 3 digits of the exponent, the CSV 6 of each time.
      EXPECT_NEAR(std::stod(cells[k]), fit.exponent, 6e-3 * std::abs(fit.exponent) + 1e-3) << solver << cells[k];
    }
  }
}

TEST_F(ScalingCommand, ReportsTheFittedExponentOfEveryStrategyThatReachedTwoSizes) {
  expectExponentsFitted(report_.summary, [](const std::string& solver, const std::string& series) {
    return reached(solver, series);
  });
}

TEST_F(ScalingCommand, ReportHasTheSeriesExponentsCrossoverAndMemorySections) {
  for (const char* section : {"## Mesh series", "## Time series", "## Growth exponents",
                              "## Against the incremental solver", "## Peak resident memory", "## Machine and build"})
    EXPECT_NE(report_.summary.find(section), std::string::npos) << section;
}

TEST_F(ScalingCommand, DrawsThePlotsOrSaysHowToDrawThemLater) {
  const std::string err = readText(report_.out / "stderr.txt");
  if (err.find("warning: gnuplot") != std::string::npos) {
    EXPECT_NE(err.find("draw them later"), std::string::npos);
    return;
  }
  for (const char* name : {"time_vs_steps.png", "time_vs_dofs.png", "memory_vs_steps.png", "memory_vs_dofs.png"})
    EXPECT_GT(fs::file_size(report_.out / "report" / name), 0u) << name;
}

// --only-at-tolerance: the solves at tolerance alone, the fits and plots on their times.
class ScalingAtToleranceOnly : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    report_.run("scaling_at_tolerance", "--arc-nodes 11,21 --steps 11,21 --repeats 1 --only-at-tolerance");
  }
  static void TearDownTestSuite() { report_.remove(); }

  /// (size, time of the solve at tolerance) of `solver` in `series` where it converged.
  static SizeTimes converged(const std::string& solver, const std::string& series) {
    SizeTimes out;
    for (const auto& row : report_.rows.rows)
      if (row.at("solver") == solver && row.at("series") == series &&
          row.at("termination_at_tolerance") == "converged")
        out.emplace_back(std::stod(row.at(series == "mesh" ? "dofs" : "steps")),
                         std::stod(row.at("time_at_tolerance_s")));
    return out;
  }

  static inline ScalingReport report_;
};

TEST_F(ScalingAtToleranceOnly, RunsNoFirstReachAndWritesNoComparisonPerSize) {
  EXPECT_EQ(report_.exit_status, 0);
  EXPECT_FALSE(fs::exists(report_.out / "report" / "sizes"));
  EXPECT_EQ(report_.summary.find("Time to first reach"), std::string::npos);
  EXPECT_NE(report_.summary.find("--only-at-tolerance"), std::string::npos);
  EXPECT_NE(report_.summary.find(" MB (interface) |"), std::string::npos);  // the incremental solver's form
  EXPECT_EQ(report_.rows.rows.size(), 4 * stc::strategyNames().size());
  for (const auto& row : report_.rows.rows) {
    EXPECT_EQ(row.at("status"), "not measured") << row.at("solver");
    EXPECT_FALSE(number(row.at("time_to_target_s")).has_value()) << row.at("solver");
    EXPECT_GT(number(row.at("time_at_tolerance_s")).value_or(0.0), 0.0) << row.at("solver");
    EXPECT_GT(number(row.at("peak_rss_mb_at_tolerance")).value_or(0.0), 0.0) << row.at("solver");
    EXPECT_TRUE(number(row.at("krylov_iterations_at_tolerance")).has_value()) << row.at("solver");
    // The incremental solver's form (on CHOLMOD `auto` takes the interface's); none for the others.
    EXPECT_EQ(row.at("incremental_form_at_tolerance"), row.at("solver") == "incremental" ? "interface" : "")
        << row.at("solver");
    // The incremental solver is exact (its true error is 0 by construction); the others are measured.
    EXPECT_TRUE(number(row.at("error_at_tolerance")).has_value()) << row.at("solver");
  }
}

TEST_F(ScalingAtToleranceOnly, ReportsTheExponentsOfTheSolvesAtTolerance) {
  ASSERT_GE(converged("incremental", "mesh").size(), 2u);
  expectExponentsFitted(report_.summary, [](const std::string& solver, const std::string& series) {
    return converged(solver, series);
  });
}

}  // namespace
}  // namespace stc
