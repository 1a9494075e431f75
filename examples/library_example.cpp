// Description
//   The library from C++ in ten lines (README.md quotes the lines between the markers): read a scene,
//   build the Problem, solve it with a strategy chosen by name, print the summary. The names are
//   those of `stcontact solve --solver` (docs/interface.md); the methods behind them: docs/method.md.
// Sample run
//   build/bin/library_example examples/scenes/hemicylinder.toml fas-apriori
//   build/bin/library_example examples/scenes/hemicylinder.toml latin mesh.arc_nodes=21 time.steps=21
//   (the second is the ctest case examples.library_example_small)
// Arguments: SCENE.toml, then optionally a strategy name (default: the scene's [solver] name) and
//   scene overrides KEY=VALUE, as `stcontact solve --set` takes them.
// Steps: 0 OpenBLAS's fastest kernels for the processor · 1 read and validate the scene · 2 assemble
//   the problem · 3 solve by name · 4 print the summary.
// Exit status: 0 converged, 1 bad input, 2 not converged, 3 internal failure.
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/strategies/registry.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: library_example SCENE.toml [SOLVER] [KEY=VALUE]...\n";
    return 1;
  }
  const std::vector<std::string> overrides(argv + (argc > 3 ? 3 : argc), argv + argc);
  std::cout << "scene " << argv[1] << ", solver " << (argc > 2 ? argv[2] : "(the scene's)") << ", overrides:";
  for (const auto& o : overrides) std::cout << ' ' << o;
  std::cout << (overrides.empty() ? " none\n" : "\n");
  try {
    // [readme-begin]
    stc::linalg::preferFastBlasKernels();                                 // 0. OpenBLAS's kernels for this CPU
    const stc::Scene scene = stc::readScene(argv[1], overrides);          // 1. read and validate
    const stc::Problem problem = stc::buildProblem(scene);                // 2. K, loads, contact interface
    const stc::Strategy strategy = argc > 2 ? stc::strategyNamed(argv[2]) : scene.solver.strategy;
    const stc::SolveResult result = stc::solve(strategy, problem, scene.solver);  // 3. solve
    const stc::SolveSummary& summary = result.summary;                    // 4. report
    std::cout << summary.solver << ": " << stc::toString(summary.termination) << " (" << summary.message
              << ")\n  " << problem.numDofs() << " dofs, " << problem.contact.size() << " contact nodes, "
              << problem.numSteps() << " instants; " << summary.relaxations << " relaxations, error estimate "
              << summary.error_estimate << ", " << summary.wall_s << " s\n";
    // [readme-end]
    return summary.converged() ? 0 : 2;
  } catch (const stc::InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "error: internal failure: " << e.what() << '\n';
    return 3;
  }
}
