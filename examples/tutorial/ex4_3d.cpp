//                               stcontact Example 4
//
// Compile with: cmake --build build --target ex4
//
// Sample runs:  build/bin/ex4 examples/scenes/hemisphere.toml
//               build/bin/ex4 examples/scenes/hemisphere.toml --set mesh.divisions=12
//               build/bin/ex4 examples/scenes/hemisphere.toml --set mesh.divisions=4 --set time.steps=41
//
// Description:  The seed's loading on a 3D body: a half-ball of tetrahedra (the half_ball
//               generator, graded toward the pole) pressed on a rigid plane, then slid along x while
//               pressed further. Every contact node has three rows (normal, two tangents) and its law
//               is the Coulomb cone; nothing else changes: the same strategies, the same options.
//
//               The example solves with the incremental solver (instant by instant, exact) and with
//               the scene's strategy (fas-apriori by default) over the whole grid, prints the contact
//               area and the total forces at a few instants from both, and exits with status 0
//               when the space-time solve converged to a true error below its tolerance.
//
//               We recommend reading Examples 1 and 3 first.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/spacetime/contact_state_table.hpp"
#include "stcontact/strategies/registry.hpp"
#include "stcontact/studies/reference.hpp"

namespace {

/// Nodes in contact (stick or slip, spacetime/contact_state_table.hpp) and the total force (normal,
/// then the two tangential components) at instant k of a contact-admissible history.
struct Forces {
  int closed = 0;
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
};

Forces forcesAt(const stc::ContactInterface& contact, const stc::InterfaceHistory& s, int k) {
  const stc::ContactStateTable states(contact, s);
  Forces f;
  const int d = contact.dimension;
  for (int i = 0; i < contact.size(); ++i) {
    f.closed += states.state(i, k) != stc::ContactState::Open;
    f.total.head(d) += s.lambda.col(k).segment(contact.normalRow(i), d);  // (λ_n, λ_t1, λ_t2)
  }
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  // 1. Parse the command line: a 3D scene and its overrides.
  CLI::App app{"stcontact example 4: a 3D scene"};
  std::string scene_file = "examples/scenes/hemisphere.toml";
  std::vector<std::string> sets;
  app.add_option("scene", scene_file, "scene file (TOML) with dimension = 3")->capture_default_str();
  app.add_option("--set", sets, "override a scene value: section.key=value")->take_all();
  CLI11_PARSE(app, argc, argv);
  try {
    stc::linalg::preferFastBlasKernels();

    // 2. The scene and its problem: `dimension = 3` gives tetrahedra and three rows per contact node.
    const stc::Scene scene = stc::readScene(scene_file, sets);
    const stc::Problem problem = stc::buildProblem(scene);
    std::cout << problem.dimension << "D: " << problem.numDofs() << " dofs, " << problem.numElements()
              << " tetrahedra, " << problem.contact.size() << " potential contact nodes, " << problem.numSteps()
              << " instants\n";

    // 3. The incremental solution (the reference) and the scene's strategy over the whole grid.
    const stc::ReferenceSolution reference = stc::computeReference(problem, nullptr);
    const stc::SolveResult result = stc::solve(problem, scene.solver, {.reference = reference.reference.get()});
    const stc::SolveSummary& s = result.summary;
    std::cout << s.solver << ": " << stc::toString(s.termination) << ", " << s.relaxations << " relaxations, true error "
              << s.error.value_or(-1.0) << ", " << s.wall_s << " s (incremental: " << reference.solve_s << " s)\n";

    // 4. Contact area and total forces at five instants, both solutions.
    std::printf("\n%8s %23s %34s %34s\n", "instant", "in contact (exact / st)", "total force (n, t1, t2), exact",
                ("total force, " + s.solver).c_str());
    const stc::SolveResult exact = stc::solveIncremental(problem);
    const stc::InterfaceHistory admissible = result.admissible();
    for (int q = 1; q <= 5; ++q) {
      const int k = q * (problem.numSteps() - 1) / 5;
      const Forces a = forcesAt(problem.contact, exact.interface, k), b = forcesAt(problem.contact, admissible, k);
      std::printf("%8d %10d / %-10d (%10.4g %10.4g %10.4g) (%10.4g %10.4g %10.4g)\n", k, a.closed, b.closed,
                  a.total[0], a.total[1], a.total[2], b.total[0], b.total[1], b.total[2]);
    }

    // 5. Converged means a true error below the tolerance, in 3D as in 2D.
    return s.converged() && s.error && *s.error <= scene.solver.tolerance() ? 0 : 2;
  } catch (const stc::InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << '\n';
    return 3;
  }
}
