// The frames of a run come from the displacement its strategy holds (docs/interface.md,
// "writer_sparse_solves"): tests of the writer with the strategies that hand one.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>

#include "fixtures/seed_scene.hpp"
#include "io/scratch_dir.hpp"
#include "stcontact/io/run_writer.hpp"
#include "stcontact/linalg/backends/cholmod_factor.hpp"
#include "stcontact/operators/displacement.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/strategies/registry.hpp"

namespace {

using stc::iotest::ScratchDir;
namespace fs = std::filesystem;

// A space-time strategy hands the writer the displacement it holds (SolveResult::displacement):
// the frames come from it with no factor of K_ff and no solve, and it is the displacement of the
// forces written, within the tolerance in the energy of A = K_ff + Bᵀ k B over the history
// (its truncation drops at most what the converged estimate leaves of τ: pgd::truncationBudget).
TEST(RunWriter, FramesOfASpaceTimeStrategyComeFromItsDisplacementWithoutASolve) {
  const stc::Scene scene = stc::test::seedScene(21, 11);
  const stc::Problem problem = stc::buildProblem(scene);
  for (const char* strategy : {"fas-apriori", "latin-pgd"}) {
    stc::PreparedOperators operators;
    stc::SolveInputs inputs;
    inputs.separated_displacement = true;
    inputs.operators = &operators;
    const stc::SolveResult result = stc::solve(stc::strategyNamed(strategy), problem, scene.solver, inputs);
    ASSERT_TRUE(result.summary.converged()) << result.summary.message;
    ASSERT_TRUE(result.displacement.held);
    const ScratchDir scratch;
    stc::OutputSpec output;
    output.frame_stride = 5;
    stc::writeRunOutputs(scratch.path(), problem, result, {}, output, operators);
    const std::string json = stc::iotest::readFile(scratch.path() / "summary.json");
    EXPECT_NE(json.find("\"writer_sparse_solves\": 0,"), std::string::npos) << json;
    for (const stc::Preparation& p : operators.preparations()) EXPECT_NE(p.name, "K_ff") << strategy;
    EXPECT_TRUE(fs::exists(scratch.path() / "solution.xdmf")) << strategy;
    // Against u(λ) solved from the forces written.
    const stc::CholmodFactor K_ff(problem.stiffness_free, "K_ff");
    const Eigen::MatrixXd solved = stc::freeDisplacements(problem, K_ff, result.interface.lambda);
    const Eigen::SparseMatrix<double> A = stc::searchDirectionOperator(problem);
    double error = 0.0, energy = 0.0;
    for (Eigen::Index k = 0; k < solved.cols(); ++k) {
      const Eigen::VectorXd d = result.displacement.at(k) - solved.col(k);
      error += d.dot(A * d);
      energy += solved.col(k).dot(A * solved.col(k));
    }
    std::cout << "[ measured ] " << strategy << ": held displacement against u(lambda), relative energy error "
              << std::sqrt(error / energy) << " with " << result.displacement.modes.cols() << " modes\n";
    EXPECT_LE(std::sqrt(error / energy), scene.solver.tolerance()) << strategy;
  }
}

}  // namespace
