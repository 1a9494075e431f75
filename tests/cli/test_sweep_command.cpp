// `stcontact sweep` end to end on the seed scene at small settings (21 contact nodes, 21 instants),
// friction 0.05 … 0.5 in 10 values, with the default solver (fas-apriori) and with latin: exit 0,
// the documented columns, every warm solve converged and in agreement with the incremental solver
// of its value, fewer relaxations warm than cold over the sweep, summary totals equal to the CSV's
// sums, plot or warning. Relaxation counts are deterministic; no wall-clock value is asserted.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/csv_table.hpp"
#include "cli/run_program.hpp"

namespace {

namespace fs = std::filesystem;

using Row = std::map<std::string, std::string>;
using Table = stc::test::CsvTable;
using stc::test::readCsv;
using stc::test::readText;

long sum(const Table& t, const std::string& column) {
  long total = 0;
  for (const Row& r : t.rows) total += std::stol(r.at(column));
  return total;
}

/// One sweep run into its own folder: exit status, sweep.csv, summary.md, stderr.
struct SweepRun {
  int exit_status = -1;
  fs::path dir;
  Table csv;
  std::string summary, stderr_text;
};

SweepRun runSweep(const fs::path& dir, const std::string& options) {
  SweepRun run;
  run.dir = dir;
  run.exit_status = stc::test::runOnSmallSeed("sweep", options, dir);
  run.csv = readCsv(dir / "report" / "sweep.csv");
  run.summary = readText(dir / "report" / "summary.md");
  run.stderr_text = readText(dir / "stderr.txt");
  return run;
}

// At indicator tolerance 1e-6 (the scene's) the true error is ~1e-5 or below: the friction sweeps of
// docs/sweep.md measured error/indicator up to 11 over every converged warm solve at these settings
// (tests/strategies/test_warm_start.cpp says the same); 2e-5 leaves a factor 1.8.
constexpr double kAgreement = 2e-5;

class SweepCommand : public ::testing::TestWithParam<std::string> {
 protected:
  static void SetUpTestSuite() {
    // ctest runs each test in its own process, possibly in parallel: one folder per process.
    scratch_ = stc::test::scratchFolder("sweep");
    for (const std::string solver : {"fas-apriori", "latin"})
      runs_[solver] = runSweep(scratch_ / solver, "--solver " + solver + " --set-range contact.friction=0.05:0.5:10");
  }
  static void TearDownTestSuite() {
    std::error_code ignored;
    fs::remove_all(scratch_, ignored);
  }
  static const SweepRun& sweep() { return runs_.at(GetParam()); }

  static inline fs::path scratch_;
  static inline std::map<std::string, SweepRun> runs_;
};

TEST_P(SweepCommand, ExitsZeroWithTheDocumentedColumnsAndOneRowPerValue) {
  EXPECT_EQ(sweep().exit_status, 0) << sweep().stderr_text;
  const std::vector<std::string> expected = {
      "value", "start", "seed_modes", "warm_termination", "warm_relaxations", "warm_sparse_solves", "warm_wall_s",
      "warm_indicator", "warm_error", "cold_termination", "cold_relaxations", "cold_sparse_solves", "cold_wall_s",
      "cold_indicator", "cold_error", "normal_force_end", "tangential_force_end", "tangential_over_normal_end",
      "reference_s"};
  EXPECT_EQ(sweep().csv.header, expected);
  ASSERT_EQ(sweep().csv.rows.size(), 10u);
  EXPECT_EQ(sweep().csv.rows.front().at("value"), "0.05");
  EXPECT_EQ(sweep().csv.rows.back().at("value"), "0.5");
  EXPECT_EQ(sweep().csv.rows.front().at("start"), "zero");
  for (std::size_t i = 1; i < sweep().csv.rows.size(); ++i) EXPECT_EQ(sweep().csv.rows[i].at("start"), "previous") << i;
}

TEST_P(SweepCommand, EveryWarmSolveConvergesToTheIncrementalSolutionOfItsValue) {
  for (const Row& r : sweep().csv.rows) {
    EXPECT_EQ(r.at("warm_termination"), "converged") << r.at("value");
    EXPECT_LE(std::stod(r.at("warm_indicator")), 1e-6) << r.at("value");
    EXPECT_LE(std::stod(r.at("warm_error")), kAgreement) << r.at("value");
    EXPECT_EQ(r.at("cold_termination"), "converged") << r.at("value");
  }
}

TEST_P(SweepCommand, WarmStartsNeedFewerRelaxationsThanColdOverTheSweep) {
  EXPECT_LT(sum(sweep().csv, "warm_relaxations"), sum(sweep().csv, "cold_relaxations"));
  // The first value has no predecessor: its warm solve is a cold one, the same deterministic iterates.
  EXPECT_EQ(sweep().csv.rows.front().at("warm_relaxations"), sweep().csv.rows.front().at("cold_relaxations"));
}

TEST_P(SweepCommand, SummaryTotalsAreTheSumsOfTheCsv) {
  const std::string warm = "| warm | " + std::to_string(sum(sweep().csv, "warm_relaxations")) + " | " +
                           std::to_string(sum(sweep().csv, "warm_sparse_solves")) + " | ";
  const std::string cold = "| cold | " + std::to_string(sum(sweep().csv, "cold_relaxations")) + " | " +
                           std::to_string(sum(sweep().csv, "cold_sparse_solves")) + " | ";
  EXPECT_NE(sweep().summary.find(warm), std::string::npos) << warm << "\n" << sweep().summary;
  EXPECT_NE(sweep().summary.find(cold), std::string::npos) << cold;
  EXPECT_NE(sweep().summary.find("Produced by `stcontact sweep"), std::string::npos);
  EXPECT_NE(sweep().summary.find("## Machine and build"), std::string::npos);
}

TEST_P(SweepCommand, EndForcesRespectTheCoulombCone) {
  // Σ|λ_t| ≤ μ Σλ_n node by node, so |T| ≤ μ N for the totals; the equilibrated iterate meets the
  // law to the solver's tolerance, hence the relative slack 1e-3.
  for (const Row& r : sweep().csv.rows) {
    ASSERT_FALSE(r.at("tangential_over_normal_end").empty()) << r.at("value");
    EXPECT_LE(std::stod(r.at("tangential_over_normal_end")), std::stod(r.at("value")) * (1.0 + 1e-3)) << r.at("value");
  }
}

TEST_P(SweepCommand, DrawsThePlotOrSaysHowToDrawItLater) {
  if (sweep().stderr_text.find("warning: gnuplot") != std::string::npos) {
    EXPECT_NE(sweep().stderr_text.find("draw them later"), std::string::npos);
    return;
  }
  EXPECT_GT(fs::file_size(sweep().dir / "report" / "sweep.png"), 0u);
}

INSTANTIATE_TEST_SUITE_P(Solvers, SweepCommand, ::testing::Values("fas-apriori", "latin"));

TEST(SweepCommandOptions, NoIndependentLeavesColdEmptyAndWriteSolutionsWritesEachValue) {
  const fs::path dir = stc::test::scratchFolder("sweep_options");
  const SweepRun result = runSweep(dir, "--solver latin --set-range contact.friction=0.1:0.3:3 --no-independent --write-solutions");
  EXPECT_EQ(result.exit_status, 0) << result.stderr_text;
  ASSERT_EQ(result.csv.rows.size(), 3u);
  for (const Row& r : result.csv.rows) {
    EXPECT_TRUE(r.at("cold_relaxations").empty()) << r.at("value");
    EXPECT_GT(fs::file_size(dir / "report" / ("value_" + r.at("value")) / "reactions.csv"), 0u) << r.at("value");
  }
  EXPECT_EQ(result.summary.find("| cold |"), std::string::npos);
  std::error_code ignored;
  fs::remove_all(dir, ignored);
}

}  // namespace
