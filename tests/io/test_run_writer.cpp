// The run outputs (src/io/run_writer.hpp) of one solution do not depend on the thread count: the VTU
// frames are written in parallel, each thread with its own solve workspace and files. A frame holds
// the stress as VTK's symmetric tensor (xx, yy, zz, xy, yz, xz) and the contact states as Int8.
#include "stcontact/io/run_writer.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <set>
#include <sstream>
#include <string>
#include <thread>

#include "fixtures/seed_scene.hpp"
#include "io/vtu_reading.hpp"
#include "scratch_dir.hpp"
#include "stcontact/core/threads.hpp"
#include "stcontact/fem/elasticity.hpp"
#include "stcontact/incremental/incremental_solver.hpp"

namespace {

using stc::iotest::ScratchDir;
namespace fs = std::filesystem;

TEST(RunWriter, FilesAreTheSameOnOneAndTwoThreads) {
  const stc::Scene scene = stc::test::seedScene(21, 81);
  const stc::Problem problem = stc::buildProblem(scene);
  const stc::SolveResult result = stc::solveIncremental(problem);
  const ScratchDir scratch;
  stc::OutputSpec output;
  output.frame_stride = 20;  // frames 0, 20, 40, 60, 80
  for (int threads : {1, 2}) {
    // More than a second apart: a time stamp left in solution.h5 (HDF5 tracks them by default, the
    // root group's too) shows as a difference at every run, not in the rare run across a second.
    if (threads == 2) std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    const stc::ThreadCountScope scope(threads);
    stc::PreparedOperators operators;
    output.format = stc::OutputFormat::Vtu;
    stc::writeRunOutputs(scratch.path() / std::to_string(threads), problem, result, {}, output, operators);
    output.format = stc::OutputFormat::Hdf5;
    stc::writeRunOutputs(scratch.path() / ("h5_" + std::to_string(threads)), problem, result, {}, output, operators);
  }
  // solution.h5: its chunks compressed on every thread, the same bytes (no time stamps)
  for (const char* name : {"solution.h5", "solution.xdmf"})
    EXPECT_EQ(stc::iotest::readFile(scratch.path() / "h5_1" / name), stc::iotest::readFile(scratch.path() / "h5_2" / name)) << name;
  const fs::path one = scratch.path() / "1", two = scratch.path() / "2";
  int frames = 0;
  for (const auto& entry : fs::directory_iterator(one / "vtu")) {
    ++frames;
    EXPECT_EQ(stc::iotest::readFile(entry.path()), stc::iotest::readFile(two / "vtu" / entry.path().filename()))
        << entry.path().filename();
  }
  EXPECT_EQ(frames, 5);
  for (const char* name : {"solution.pvd", "contact.csv", "reactions.csv"})
    EXPECT_EQ(stc::iotest::readFile(one / name), stc::iotest::readFile(two / name)) << name;
  EXPECT_NE(stc::iotest::readFile(one / "vtu" / "step_00000.vtu"), stc::iotest::readFile(one / "vtu" / "step_00080.vtu"));
}

// The displacement read back (Float64) gives, through the element stresses (rows xx, yy, xy, zz, von
// Mises), the tensor of the frame in VTK's order, with σ_zz = ν(σ_xx + σ_yy) (plane strain) and
// σ_yz = σ_xz = 0.
TEST(RunWriter, FramesHoldTheStressTensorInVtkOrderAndTheStatesAsInt8) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(21, 81));
  const stc::SolveResult result = stc::solveIncremental(problem);
  const ScratchDir scratch;
  stc::OutputSpec output;
  output.frame_stride = 80;
  output.format = stc::OutputFormat::Vtu;
  output.field_precision = stc::FieldPrecision::Float64;
  stc::PreparedOperators operators;
  stc::writeRunOutputs(scratch.path(), problem, result, {}, output, operators);
  const auto file = stc::iotest::readVtu(stc::iotest::readFile(scratch.path() / "vtu" / "step_00080.vtu"));
  const auto& u = file.array("PointData", "displacement").values;  // x, y, 0 per node
  Eigen::VectorXd dofs(2 * problem.numNodes());
  for (int j = 0; j < problem.numNodes(); ++j) dofs.segment<2>(2 * j) << u[3 * j], u[3 * j + 1];
  const auto sigma = stc::elementStresses(std::get<stc::TriMesh>(problem.body), problem.material, problem.plane, dofs);
  const auto& tensor = file.array("CellData", "stress").values;
  ASSERT_EQ(tensor.size(), 6u * problem.numElements());
  const double scale = sigma.topRows(4).cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  const int vtkRowOf[6] = {0, 1, 3, 2, -1, -1};  // XX, YY, ZZ, XY, YZ, XZ from rows xx, yy, xy, zz
  for (int e = 0; e < problem.numElements(); ++e) {
    for (int c = 0; c < 6; ++c)
      EXPECT_NEAR(tensor[6 * e + c], vtkRowOf[c] < 0 ? 0.0 : sigma(vtkRowOf[c], e), 1e-12 * scale) << e << ' ' << c;
    EXPECT_NEAR(tensor[6 * e + 2], problem.material.poisson * (tensor[6 * e] + tensor[6 * e + 1]), 1e-12 * scale) << e;
  }
  const auto& states = file.array("PointData", "contact_state");
  EXPECT_EQ(states.attributes.at("type"), "Int8");
  const std::set<double> codes(states.values.begin(), states.values.end());
  for (double code : codes) EXPECT_TRUE(code == -1 || code == 0 || code == 1 || code == 2) << code;
  EXPECT_TRUE(codes.count(-1) && codes.count(2)) << "t = 1 slides: contact nodes slip, the others are not contact nodes";
  EXPECT_EQ(file.array("PointData", "displacement").attributes.at("type"), "Float64");
}

}  // namespace

namespace {

// The sparse solves a solve spent are in history.csv (the last column, each record's count so far)
// and in summary.json (the last record's): for the incremental solver on every node, the Delassus
// columns and the load terms, the same count on every instant.
TEST(RunWriter, HistoryAndSummaryCarryTheSparseSolvesSpent) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(21, 11));
  stc::IncrementalOptions every_node;
  every_node.zone_within_reach = false;
  const stc::SolveResult result = stc::solveIncremental(problem, every_node);
  const std::string csv = stc::historyCsv(result.summary);
  std::istringstream lines(csv);
  std::string header, row;
  std::getline(lines, header);
  EXPECT_EQ(header, "iteration,relaxations,indicator,error,rank,wall_s,error_estimate,sparse_solves,krylov_iterations");
  const int spent = result.summary.sparseSolves();
  EXPECT_EQ(spent, 2 * 21 + static_cast<int>(problem.loads.size()));
  int rows = 0;
  while (std::getline(lines, row)) {
    ++rows;
    // sparse_solves, then krylov_iterations: 0 on CHOLMOD
    EXPECT_EQ(row.substr(row.rfind(',') - std::to_string(spent).size(), std::string::npos), std::to_string(spent) + ",0")
        << row;
  }
  EXPECT_EQ(rows, 11);
  const std::string json = stc::summaryJson(problem, result.summary, {"{}", "test", {}, {}, {}}, {});
  EXPECT_NE(json.find("\"relaxations\": 0,\n  \"sparse_solves\": " + std::to_string(spent) + ","), std::string::npos)
      << json;
  EXPECT_NE(json.find("\"sub_grid\": null,"), std::string::npos) << json;
  EXPECT_NE(json.find("\"incremental_form\": \"interface\","), std::string::npos) << json;  // CHOLMOD: no choice
}

// A solve nested in time says what its sub-grid solve spent, beside the whole solve's counts that
// include it (docs/interface.md, summary.json).
TEST(RunWriter, SummaryCarriesTheSubGridSolve) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(21, 11));
  stc::SolveSummary summary;
  summary.solver = "fas-apriori";
  stc::SolveStage zone;
  zone.kind = stc::SolveStage::Kind::ContactZone;
  stc::SolveStage sub_grid;
  sub_grid.relaxations = 19;
  sub_grid.sparse_solves = 185;
  sub_grid.wall_s = 0.25;
  summary.stages = {sub_grid, zone};
  const std::string json = stc::summaryJson(problem, summary, {"{}", "test", {}, {}, {}}, {});
  EXPECT_NE(json.find("\"incremental_form\": null,"), std::string::npos) << json;  // not the incremental solver
  EXPECT_NE(json.find("\"sub_grid\": {\n    \"relaxations\": 19,\n    \"sparse_solves\": 185,\n    \"wall_s\": 0.25\n  },"),
            std::string::npos)
      << json;
}

}  // namespace

// The frames take K_ff from the run's operators: a factor prepared before (by the solve, the
// reference) is used, not prepared again, and summary.json lists it once with both uses.
TEST(RunWriter, FramesUseTheRunsFactorAndTheSummaryListsIt) {
  const stc::Problem problem = stc::buildProblem(stc::test::seedScene(21, 11));
  stc::PreparedOperators operators;
  const stc::SolveResult result = stc::solveIncremental(problem, {}, {.operators = &operators});
  const ScratchDir scratch;
  stc::OutputSpec output;
  output.frame_stride = 5;
  stc::writeRunOutputs(scratch.path(), problem, result, {}, output, operators);
  const std::vector<stc::Preparation> prepared = operators.preparations();
  ASSERT_EQ(prepared.size(), 1u);
  EXPECT_EQ(prepared[0].name, "K_ff");
  EXPECT_EQ(prepared[0].uses, 2);  // the incremental solve, then the frames
  const std::string json = stc::iotest::readFile(scratch.path() / "summary.json");
  EXPECT_NE(json.find("\"preparations\": [\n    {\n      \"operator\": \"K_ff\",\n      \"backend\": \"cholmod\",\n      \"rows\": " +
                      std::to_string(problem.numFreeDofs()) + ","),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"uses\": 2"), std::string::npos) << json;
  EXPECT_NE(json.find("\"writer_sparse_solves\": 3,"), std::string::npos) << json;  // frames 0, 5, 10
}

