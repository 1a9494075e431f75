//                               stcontact Example 1
//
// Compile with: cmake --build build --target ex1            (STC_BUILD_TESTS=ON builds every example)
//
// Sample runs:  build/bin/ex1 examples/scenes/hemicylinder.toml
//               build/bin/ex1 examples/scenes/hemicylinder.toml --tol 1e-8 --relaxation 0.8
//               build/bin/ex1 examples/scenes/hemicylinder.toml --set mesh.arc_nodes=21 --set time.steps=21
//
// Description:  This example solves the seed scene of Giacoma et al. (CSMA 2013): an elastic
//               half-disc pressed on a rigid plane and slid along it, with Coulomb friction, over
//               201 instants. LATIN (docs/method.md §2) solves the whole space-time grid at once:
//               a local stage (the contact law, node by node and instant by instant) and a global
//               stage (equilibrium: one factorisation of K + Bᵀ k B, every instant a right-hand
//               side) alternate until the estimate of the true error is below the tolerance.
//
//               The incremental solver, exact to round-off, is the reference: the true error of
//               every iterate is printed beside the estimate the solve stops on. The example exits
//               with status 0 when LATIN converged to a true error below the tolerance.
//
//               We recommend reading this example first: the others repeat its steps.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/latin/latin_solver.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/studies/reference.hpp"

int main(int argc, char** argv) {
  // 1. Parse the command line: the scene, its overrides (as `stcontact solve --set` takes them),
  //    LATIN's tolerance on the error estimate and its relaxation ω.
  CLI::App app{"stcontact example 1: LATIN over the whole space-time grid"};
  std::string scene_file = "examples/scenes/hemicylinder.toml";
  std::vector<std::string> sets;
  double tolerance = 1e-6, relaxation = 1.0;
  app.add_option("scene", scene_file, "scene file (TOML)")->capture_default_str();
  app.add_option("--set", sets, "override a scene value: section.key=value")->take_all();
  app.add_option("--tol", tolerance, "tolerance on the error estimate")->capture_default_str();
  app.add_option("--relaxation", relaxation, "LATIN's relaxation ω in (0, 1]")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    stc::linalg::preferFastBlasKernels();  // OpenBLAS's fastest kernels for this processor

    // 2. Read and validate the scene, then assemble the problem: P1 elasticity, the Dirichlet
    //    conditions eliminated, the loads in separated form, the contact interface B and its gaps.
    const stc::Scene scene = stc::readScene(scene_file, sets);
    const stc::Problem problem = stc::buildProblem(scene);
    std::cout << problem.numDofs() << " dofs, " << problem.contact.size() << " contact nodes, "
              << problem.numSteps() << " instants\n";

    // 3. The reference: the incremental solution and the true-error measure on it (the relative
    //    energy of the displacement error over the grid, docs/method.md §2).
    const stc::ReferenceSolution reference = stc::computeReference(problem, nullptr);

    // 4. LATIN's options: the scene's, with the tolerance and relaxation of the command line
    //    (src/options/latin_options.hpp lists every field, its default and its range).
    stc::latin::LatinOptions options = scene.solver.latin;
    options.stop.tolerance = tolerance;
    options.relaxation = relaxation;

    // 5. Solve from s = 0, the true error of every iterate recorded in the history.
    const stc::SolveResult result = stc::latin::solveLatin(problem, options, {.reference = reference.reference.get()});

    // 6. The history every tenth iteration, then the summary.
    std::printf("%9s %12s %12s %12s\n", "iteration", "indicator", "estimate", "true error");
    for (const stc::IterationRecord& r : result.summary.history)
      if (r.iteration % 10 == 0 || r.iteration == result.summary.iterations)
        std::printf("%9d %12.3e %12.3e %12.3e\n", r.iteration, r.indicator, r.error_estimate, r.error.value_or(-1.0));
    const stc::SolveSummary& s = result.summary;
    std::cout << s.solver << ": " << stc::toString(s.termination) << " (" << s.message << "), " << s.wall_s << " s\n";

    // 7. What the stopping rule promises: converged means a true error below the tolerance.
    return s.converged() && s.error && *s.error <= tolerance ? 0 : 2;
  } catch (const stc::InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << '\n';
    return 3;
  }
}
