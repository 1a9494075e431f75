//                               stcontact Example 5
//
// Compile with: cmake --build build --target ex5
//
// Sample runs:  build/bin/ex5 examples/scenes/hemicylinder.toml
//               build/bin/ex5 examples/scenes/hemicylinder.toml --range contact.friction=0.1:0.6:6
//               build/bin/ex5 examples/scenes/hemicylinder.toml --set mesh.arc_nodes=21 --set time.steps=41
//
// Description:  A parameter study, as a user scripts it: the seed scene solved for several values of
//               one key (by default the Coulomb coefficient), each value twice with the scene's
//               strategy: cold, from s = 0, and warm, from the previous value's solution. A warm
//               start (SolveInputs::start, src/solver/warm_start.hpp) changes where the iteration
//               begins, not where it ends; with a separated global stage (fas-apriori, latin-pgd)
//               the previous solve's interface directions seed the new basis too
//               (SolveInputs::basis_seed). `stcontact sweep` runs the same study with its report
//               (docs/sweep.md).
//
//               The example prints the relaxations and sparse solves of both starts per value, and
//               exits with status 0 when every solve converged to a true error below the tolerance.
//
//               We recommend reading Examples 1 and 3 first.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/scene/sweep_range.hpp"
#include "stcontact/strategies/registry.hpp"
#include "stcontact/studies/reference.hpp"

namespace {

bool agrees(const stc::SolveSummary& s, double tolerance) { return s.converged() && s.error && *s.error <= tolerance; }

}  // namespace

int main(int argc, char** argv) {
  // 1. Parse the command line: the scene, its overrides, and the range KEY=FROM:TO:COUNT.
  CLI::App app{"stcontact example 5: a warm-started parameter sweep"};
  std::string scene_file = "examples/scenes/hemicylinder.toml";
  std::string range_text = "contact.friction=0.05:0.5:4";
  std::vector<std::string> sets;
  app.add_option("scene", scene_file, "scene file (TOML)")->capture_default_str();
  app.add_option("--range", range_text, "KEY=FROM:TO:COUNT, evenly spaced values")->capture_default_str();
  app.add_option("--set", sets, "override a scene value for every solve: section.key=value")->take_all();
  CLI11_PARSE(app, argc, argv);
  try {
    stc::linalg::preferFastBlasKernels();
    const stc::SweepRange range = stc::parseSweepRange(range_text);

    // 2. One value after the other: its scene (the overrides, then KEY=VALUE), its problem (the
    //    factorisation depends on the value when it changes the search direction), its reference.
    std::optional<stc::SolveResult> previous;
    int cold_total = 0, warm_total = 0;
    bool all_agree = true;
    std::printf("%-24s %18s %18s\n", "value", "cold: relax/solves", "warm: relax/solves");
    for (std::size_t i = 0; i < range.values.size(); ++i) {
      std::vector<std::string> overrides = sets;
      overrides.push_back(range.override(i));
      const stc::Scene scene = stc::readScene(scene_file, overrides);
      const stc::Problem problem = stc::buildProblem(scene);
      const stc::ReferenceSolution reference = stc::computeReference(problem, nullptr);

      // 3. Cold: from s = 0.
      stc::SolveInputs cold{.reference = reference.reference.get()};
      const stc::SolveSummary c = stc::solve(problem, scene.solver, cold).summary;

      // 4. Warm: from the previous value's solution and, for a separated stage, its directions.
      stc::SolveInputs warm = cold;
      if (previous) {
        warm.start = &previous->interface;
        if (previous->interface_directions.cols() > 0) warm.basis_seed = &previous->interface_directions;
      }
      stc::SolveResult w = stc::solve(problem, scene.solver, warm);

      std::printf("%-24s %9d / %-6d %9d / %-6d\n", range.override(i).c_str(), c.relaxations, c.sparseSolves(),
                  w.summary.relaxations, w.summary.sparseSolves());
      cold_total += c.relaxations;
      warm_total += w.summary.relaxations;
      all_agree = all_agree && agrees(c, scene.solver.tolerance()) && agrees(w.summary, scene.solver.tolerance());
      previous = std::move(w);
    }
    std::cout << "relaxations in all: cold " << cold_total << ", warm " << warm_total << '\n';

    // 5. Both starts reach the same solutions: the start is a path, not an answer.
    return all_agree ? 0 : 2;
  } catch (const stc::InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << '\n';
    return 3;
  }
}
