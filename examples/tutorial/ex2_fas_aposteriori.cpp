//                               stcontact Example 2
//
// Compile with: cmake --build build --target ex2
//
// Sample runs:  build/bin/ex2 examples/scenes/hemicylinder.toml
//               build/bin/ex2 examples/scenes/hemicylinder.toml --modes 4 --residual-vectors 5
//               build/bin/ex2 examples/scenes/hemicylinder.toml --set mesh.arc_nodes=21 --set time.steps=21
//
// Description:  The two-level nonlinear multigrid (FAS) of the seed paper (§4; docs/method.md §4),
//               with LATIN as the smoother and, as its coarse space, the a posteriori basis: the
//               leading space-time SVD modes of a converged solution (here the incremental one)
//               and residual vectors renewed every cycle. One cycle: ν1 relaxations, a coarse step
//               (i_C restricted LATIN iterations in the coarse space), ν2 relaxations.
//
//               The basis needs the solution first: it is the yardstick the a priori basis of
//               Example 3 is measured against. The example solves with LATIN and with FAS to the
//               same tolerance and prints the relaxations each needs; it exits with status 0 when FAS
//               converged, agrees with the incremental solution and needed fewer relaxations.
//
//               We recommend reading Example 1 first.
#include <CLI/CLI.hpp>

#include <iostream>
#include <string>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/fas/aposteriori/solve_fas_aposteriori.hpp"
#include "stcontact/latin/latin_solver.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/studies/reference.hpp"

namespace {

void print(const stc::SolveSummary& s) {
  std::cout << "  " << s.solver << ": " << stc::toString(s.termination) << ", " << s.relaxations
            << " relaxations, " << s.sparseSolves() << " sparse solves, true error "
            << s.error.value_or(-1.0) << ", " << s.wall_s << " s\n";
}

}  // namespace

int main(int argc, char** argv) {
  // 1. Parse the command line: the scene, its overrides, the size of the a posteriori basis.
  CLI::App app{"stcontact example 2: FAS with the a posteriori (SVD) basis"};
  std::string scene_file = "examples/scenes/hemicylinder.toml";
  std::vector<std::string> sets;
  stc::fas::FasAposterioriOptions options;  // the defaults of src/options/fas_aposteriori_options.hpp
  app.add_option("scene", scene_file, "scene file (TOML)")->capture_default_str();
  app.add_option("--set", sets, "override a scene value: section.key=value")->take_all();
  app.add_option("--modes", options.basis.svd_modes, "leading SVD modes in the coarse space")->capture_default_str();
  app.add_option("--residual-vectors", options.basis.residual_vectors, "residual vectors per cycle")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    stc::linalg::preferFastBlasKernels();

    // 2. The scene and its problem, as in Example 1.
    const stc::Scene scene = stc::readScene(scene_file, sets);
    const stc::Problem problem = stc::buildProblem(scene);

    // 3. The incremental solution: the reference of the true error, and the converged solution
    //    whose SVD modes form the coarse space.
    const stc::ReferenceSolution reference = stc::computeReference(problem, nullptr);
    stc::SolveInputs inputs;
    inputs.reference = reference.reference.get();
    inputs.converged_lambda = &reference.reference->referenceForces();

    // 4. FAS's options: the scene's cycle (ν1, ν2, i_C, the safeguard...) and stopping rule, this
    //    command line's basis.
    options.fas = scene.solver.fas_aposteriori.fas;

    // 5. LATIN, then FAS, from s = 0 to the same tolerance.
    std::cout << problem.numDofs() << " dofs, " << problem.contact.size() << " contact nodes, "
              << problem.numSteps() << " instants; coarse space: " << options.basis.svd_modes << " SVD modes + "
              << options.basis.residual_vectors << " residual vectors\n";
    const stc::SolveResult latin = stc::latin::solveLatin(problem, scene.solver.latin, inputs);
    const stc::SolveResult fas = stc::fas::solveFasAposteriori(problem, options, inputs);
    print(latin.summary);
    print(fas.summary);

    // 6. FAS converged, to the incremental solution, in fewer relaxations than LATIN.
    const double tolerance = options.fas.stop.tolerance;
    const bool agrees = fas.summary.converged() && fas.summary.error && *fas.summary.error <= tolerance;
    return agrees && fas.summary.relaxations < latin.summary.relaxations ? 0 : 2;
  } catch (const stc::InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << '\n';
    return 3;
  }
}
