// An earlier run's solution.h5 read back (src/io/stored_solution.hpp): the contact forces the writer
// stored, bit for bit, its figures, and the checks that refuse a file solved on another model or
// not written by stcontact.
#include "stcontact/io/stored_solution.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "scratch_dir.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/core/missing_file_error.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/io/run_writer.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace {

using stc::iotest::ScratchDir;

// The seed scene of the examples at small settings, read as a user's (its model recorded).
stc::Scene seed(int arc_nodes) {
  return stc::readScene(std::filesystem::path(STC_SOURCE_DIR) / "examples/scenes/hemicylinder.toml",
                        {"mesh.arc_nodes=" + std::to_string(arc_nodes), "time.steps=41"});
}

struct Written {
  stc::Scene scene = seed(21);
  stc::Problem problem = stc::buildProblem(scene);
  stc::SolveResult result = stc::solveIncremental(problem);
  ScratchDir scratch;

  Written() {
    stc::OutputSpec output;
    output.frames = false;
    stc::PreparedOperators operators;
    stc::RunInfo info;
    info.model_json = scene.model_json;
    stc::writeRunOutputs(scratch.path(), problem, result, info, output, operators);
  }
  std::filesystem::path file() const { return scratch.path() / "solution.h5"; }
};

TEST(StoredSolution, ReadsBackTheForcesAndFiguresWritten) {
  const Written w;
  const stc::StoredSolution s = stc::readStoredSolution(w.file());
  EXPECT_EQ(s.solver, w.result.summary.solver);
  EXPECT_EQ(s.dimension, 2);
  EXPECT_EQ(s.dofs, w.problem.numDofs());
  EXPECT_EQ(s.contact_nodes, w.problem.contact.size());
  EXPECT_EQ(s.steps, 41);
  EXPECT_EQ(s.model_json, w.scene.model_json);
  EXPECT_EQ(s.model_json.find("\"solver\""), std::string::npos);  // [solver] is not the model's
  ASSERT_EQ(s.lambda.rows(), w.result.interface.lambda.rows());
  ASSERT_EQ(s.lambda.cols(), w.result.interface.lambda.cols());
  EXPECT_EQ((s.lambda - w.result.interface.lambda).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(s.lambda.cwiseAbs().maxCoeff(), 0.0);  // the seed presses: forces to compare
  EXPECT_NO_THROW(stc::requireSolvedOn(s, w.problem, w.scene.model_json));
}

TEST(StoredSolution, RefusesAnotherModelOrSizes) {
  const Written w;
  const stc::StoredSolution s = stc::readStoredSolution(w.file());
  const stc::Scene finer = seed(31);
  EXPECT_THROW(stc::requireSolvedOn(s, stc::buildProblem(finer), finer.model_json), stc::InputError);
  // The same sizes, another model: its text differs.
  EXPECT_THROW(stc::requireSolvedOn(s, w.problem, w.scene.model_json + " "), stc::InputError);
  // A file without its model (written before it was kept) cannot be checked.
  stc::StoredSolution old = s;
  old.model_json.clear();
  EXPECT_THROW(stc::requireSolvedOn(old, w.problem, w.scene.model_json), stc::InputError);
}

TEST(StoredSolution, RefusesWhatIsNotASolutionFile) {
  const ScratchDir scratch;
  EXPECT_THROW(stc::readStoredSolution(scratch.path() / "none.h5"), stc::MissingFileError);
  std::ofstream(scratch.path() / "text.h5") << "not hdf5\n";
  EXPECT_THROW(stc::readStoredSolution(scratch.path() / "text.h5"), stc::InputError);
}

}  // namespace
