// solution.h5's tables and choices (src/io/contact_tables.hpp, frame_fields.hpp, run_writer.hpp):
// the interface histories beside λ (slip 0 where open), the frames' automatic stride within its
// budget, when contact.csv is written, and a solution file that cannot be written failing with its
// name and leaving no temporary. The file read back by independent readers (h5py, meshio's XDMF
// reader): tests/io/solution_read_back.py.
#include "stcontact/io/solution_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "fixtures/seed_scene.hpp"
#include "scratch_dir.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/io/output_error.hpp"
#include "stcontact/io/run_writer.hpp"
#include "stcontact/spacetime/contact_state_table.hpp"

namespace {

namespace fs = std::filesystem;

TEST(InterfaceTable, GapSlipAndStateAreThoseOfTheInterfaceWithNoSlipWhereOpen) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(21, 41));
  const stc::SolveResult result = stc::solveIncremental(problem);
  const stc::InterfaceTable table = stc::interfaceTable(problem, result);
  const stc::ContactStateTable states = result.contactStates(problem.contact);
  const auto& c = problem.contact;
  ASSERT_EQ(table.steps, 41);
  ASSERT_EQ(table.nodes, c.size());
  int open = 0, slipping = 0;
  for (int k = 0; k < table.steps; ++k)
    for (int i = 0; i < table.nodes; ++i) {
      const auto at = static_cast<std::size_t>(k * table.nodes + i);
      const stc::ContactState state = states.state(i, k);
      EXPECT_EQ(table.state[at], static_cast<std::int8_t>(state));
      EXPECT_EQ(table.gap[at], c.initial_gap[i] + result.interface.v(c.normalRow(i), k));
      const double jump = result.interface.v(c.normalRow(i) + 1, k) - (k > 0 ? result.interface.v(c.normalRow(i) + 1, k - 1) : 0.0);
      EXPECT_EQ(table.slip[at], state == stc::ContactState::Open ? 0.0 : jump) << k << ' ' << i;
      open += state == stc::ContactState::Open && jump != 0.0;
      slipping += state == stc::ContactState::Slip;
    }
  EXPECT_GT(open, 0);      // open nodes that moved along the obstacle: their motion is not slip
  EXPECT_GT(slipping, 0);  // and the seed's drag makes nodes slip
}

// 4 bytes for each of 2d + 1 nodal values and 7 element values: io/frame_fields.hpp's count.
double frameBytes(const stc::Problem& p) { return 4.0 * ((2.0 * p.dimension + 1.0) * p.numNodes() + 7.0 * p.numElements()); }

TEST(FrameStride, AutoKeepsEveryInstantOfASmallRunAndTheBudgetOfALongOne) {
  const stc::Problem small = stc::buildProblem(stc::test::seedScene(21, 41));
  EXPECT_EQ(stc::autoFrameStride(small), 1);
  EXPECT_EQ(stc::frameStride(small, 0), 1);
  EXPECT_EQ(stc::frameStride(small, 7), 7);  // a stride given is the stride used
  const stc::Problem seed = stc::buildProblem(stc::test::seedScene());
  EXPECT_EQ(stc::autoFrameStride(seed), 1);  // the seed's 201 frames fit
  const stc::Problem many = stc::buildProblem(stc::test::seedScene(101, 4001));
  const int stride = stc::autoFrameStride(many);
  const auto frames = static_cast<double>(stc::frameSteps(many.numSteps(), stride).size());
  EXPECT_GT(stride, 1);
  EXPECT_LE(frames * frameBytes(many), stc::kAutoFrameBytes);
  const auto finer = static_cast<double>(stc::frameSteps(many.numSteps(), stride - 1).size());
  EXPECT_GT(finer * frameBytes(many), stc::kAutoFrameBytes);  // the smallest stride that fits
}

TEST(ContactCsv, WrittenWhileSmallOrWhenAsked) {
  const stc::Problem seed = stc::buildProblem(stc::test::seedScene());
  const stc::Problem long_run = stc::buildProblem(stc::test::seedScene(101, 8001));
  stc::OutputSpec output;
  EXPECT_TRUE(stc::writesContactCsv(seed, output));
  EXPECT_FALSE(stc::writesContactCsv(long_run, output));
  EXPECT_GT(stc::contactCsvBytes(long_run), stc::kSmallContactCsvBytes);
  output.contact_csv = stc::ContactCsv::Always;
  EXPECT_TRUE(stc::writesContactCsv(long_run, output));
  output.contact_csv = stc::ContactCsv::Never;
  EXPECT_FALSE(stc::writesContactCsv(seed, output));
}

TEST(SolutionFile, AFileThatCannotBeWrittenNamesItselfAndLeavesNoTemporary) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(21, 11));
  const stc::SolveResult result = stc::solveIncremental(problem);
  const stc::iotest::ScratchDir scratch;
  const fs::path blocked = scratch.path() / "solution.h5";
  fs::create_directory(blocked);  // a folder where the file goes: the rename over it fails
  stc::PreparedOperators operators;
  const stc::RunTables tables{stc::interfaceTable(problem, result), stc::reactionTable(problem, result)};
  try {
    stc::writeSolutionFile(scratch.path(), problem, result, tables, {}, {}, true, operators);
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("solution.h5"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(scratch.path() / ".solution.h5.tmp"));
  EXPECT_THROW(stc::writeSolutionH5(scratch.path() / "missing" / "solution.h5", problem, result, tables, {}, {}),
               stc::OutputError);
}

TEST(SolutionFile, TheXdmfIndexListsEveryFrameWithItsTimeAndTheSharedMesh) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(21, 11));
  const std::string xdmf = stc::xdmfDocument("solution.h5", problem, {0, 5, 10}, stc::FieldPrecision::Float32);
  for (const char* part : {"CollectionType=\"Temporal\"", "<Time Value=\"0.5\"/>", "solution.h5:/frames/step_00010/stress",
                           "TopologyType=\"Triangle\"", "solution.h5:/mesh/points", "AttributeType=\"Tensor6\""})
    EXPECT_NE(xdmf.find(part), std::string::npos) << part;
  std::size_t grids = 0;
  for (std::size_t at = xdmf.find("GridType=\"Uniform\""); at != std::string::npos; at = xdmf.find("GridType=\"Uniform\"", at + 1)) ++grids;
  EXPECT_EQ(grids, 3u);
}

}  // namespace
