// The run outputs (src/io/run_writer.hpp) of one solution do not depend on the thread count: the VTU
// frames are written in parallel, each thread with its own solve workspace and files.
#include "stcontact/io/run_writer.hpp"

#include <gtest/gtest.h>

#include "fixtures/seed_scene.hpp"
#include "scratch_dir.hpp"
#include "stcontact/core/threads.hpp"
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
  output.vtu_stride = 20;  // frames 0, 20, 40, 60, 80
  for (int threads : {1, 2}) {
    const stc::ThreadCountScope scope(threads);
    stc::writeRunOutputs(scratch.path() / std::to_string(threads), problem, result, {}, output);
  }
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

}  // namespace
