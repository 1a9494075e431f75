// `stcontact solve` prepares each operator once (src/operators/prepared_operators.hpp): the
// incremental reference, the true-error measure, the solve and the frames (of a strategy that holds
// no displacement) share the one factor of K_ff, and summary.json lists what the run prepared, by
// operator.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli/run_program.hpp"

namespace stc {
namespace {

namespace fs = std::filesystem;

struct Prepared {
  std::string name;
  int contact_nodes = 0;
  int uses = 0;
};

// The entries of summary.json's "preparations", as the writer lays them out (one member a line).
std::vector<Prepared> preparations(const fs::path& summary) {
  std::ifstream in(summary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string json = text.str();
  const auto begin = json.find("\"preparations\": [");
  if (begin == std::string::npos) return {};
  const std::string list = json.substr(begin, json.find("\n  ]", begin) - begin);
  std::vector<Prepared> out;
  const std::regex entry(R"re(\{\s*"operator": "([^"]+)",\s*"backend": "cholmod",\s*"rows": \d+,\s*(?:"contact_nodes": (\d+),\s*)?)re"
                         R"re("factor_nonzeros": [^,]+,\s*"seconds": [^,]+,\s*"uses": (\d+))re");
  for (auto it = std::sregex_iterator(list.begin(), list.end(), entry); it != std::sregex_iterator(); ++it)
    out.push_back({(*it)[1], (*it)[2].matched ? std::stoi((*it)[2]) : 0, std::stoi((*it)[3])});
  return out;
}

class SolvePreparations : public ::testing::Test {
 protected:
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  std::vector<Prepared> solve(const std::string& options) {
    dir_ = test::scratchFolder("preparations");
    EXPECT_EQ(test::runOnSmallSeed("solve", options + " --set output.frame_stride=10", dir_), 0);
    return preparations(dir_ / "report" / "summary.json");
  }
  fs::path dir_;
};

// The incremental solve and its frames: one factor of K_ff, used twice.
TEST_F(SolvePreparations, IncrementalWithItsFramesPreparesTheStiffnessOnce) {
  const std::vector<Prepared> prepared = solve("--solver incremental");
  ASSERT_EQ(prepared.size(), 1u);
  EXPECT_EQ(prepared[0].name, "K_ff");
  EXPECT_EQ(prepared[0].uses, 2);
}

// The default solve: the reference's K_ff (its incremental solve, the true error's measure; the
// frames come from fas-apriori's own displacement, without it), and each search operator of
// fas-apriori's contact zones once.
TEST_F(SolvePreparations, DefaultSolvePreparesEachOperatorOnce) {
  const std::vector<Prepared> prepared = solve("");
  ASSERT_GE(prepared.size(), 2u);
  int stiffness = 0;
  for (const Prepared& p : prepared) {
    if (p.name == "K_ff") {
      ++stiffness;
      EXPECT_EQ(p.uses, 2);
    } else {
      EXPECT_EQ(p.name, "K_ff + B^T k B");
      EXPECT_GT(p.contact_nodes, 0);
    }
  }
  EXPECT_EQ(stiffness, 1);
  for (std::size_t a = 0; a < prepared.size(); ++a)  // distinct operators: distinct interfaces here
    for (std::size_t b = a + 1; b < prepared.size(); ++b)
      if (prepared[a].name == prepared[b].name) EXPECT_NE(prepared[a].contact_nodes, prepared[b].contact_nodes);
}

}  // namespace
}  // namespace stc
