//                               stcontact Example 3
//
// Compile with: cmake --build build --target ex3
//
// Sample runs:  build/bin/ex3 examples/scenes/hemicylinder.toml
//               build/bin/ex3 examples/scenes/hemicylinder.toml --set time.steps=801
//               build/bin/ex3 examples/scenes/hemicylinder.toml --set mesh.arc_nodes=21 --set time.steps=21
//
// Description:  `fas-apriori`, the default strategy (docs/method.md §5): the two-level FAS of
//               Example 2 whose coarse space is built a priori, during the iterations, from the
//               separated (PGD) expansion of the fine level's global stage: the leading energy modes
//               of that expansion and of its latest change. No SVD of a converged solution.
//
//               First the solve a user gets, through the registry (strategies/registry.hpp): the
//               scene's [solver] table chooses the strategy and sets its options. Then the same
//               problem with one option changed at a time, to show what each ingredient gives: the
//               reduced interface (the contact nodes that can touch), the anticipated expansion,
//               the size of the coarse space. Every variant must reach the incremental solution.
//
//               We recommend reading Examples 1 and 2 first.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/fas/apriori/solve_fas_apriori.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/strategies/registry.hpp"
#include "stcontact/studies/reference.hpp"

namespace {

struct Variant {
  const char* what;
  std::function<void(stc::fas::FasAprioriOptions&)> change;
};

// Step 2 as a program of one's own would write it: the solve of `stcontact solve` (the strategy the
// scene names, with its options, and the incremental solution as the reference of the true error),
// and a bad scene reported: stc::InputError names the file, the key and the rule in one line.
// [readme-begin]
int solveAsTheProgram(const std::string& scene_file, const std::vector<std::string>& sets) try {
  const stc::Scene scene = stc::readScene(scene_file, sets);              // read and validate
  const stc::Problem problem = stc::buildProblem(scene);                  // K, loads, contact interface
  const stc::ReferenceSolution reference = stc::computeReference(problem, nullptr);  // incremental
  const stc::SolveInputs inputs{.reference = reference.reference.get()};  // true errors in the history
  const stc::SolveResult result = stc::solve(problem, scene.solver, inputs);  // the scene's strategy
  const stc::SolveSummary& summary = result.summary;
  std::cout << summary.solver << ": " << stc::toString(summary.termination) << " (" << summary.message << ")\n  "
            << problem.numDofs() << " dofs, " << problem.contact.size() << " contact nodes, "
            << problem.numSteps() << " instants; " << summary.relaxations << " relaxations, true error "
            << summary.error.value_or(-1.0) << ", " << summary.wall_s << " s\n";
  for (const stc::SolveStage& stage : summary.stages)  // the sub-grid solve, the contact zone
    std::cout << "  stage: " << stage.description << '\n';
  return summary.converged() && summary.error && *summary.error <= scene.solver.tolerance() ? 0 : 2;
} catch (const stc::InputError& e) {  // a bad scene or option: one line, exit status 1
  std::cerr << "error: " << e.what() << '\n';
  return 1;
}
// [readme-end]

}  // namespace

int main(int argc, char** argv) {
  // 1. Parse the command line: the scene and its overrides.
  CLI::App app{"stcontact example 3: fas-apriori and its options"};
  std::string scene_file = "examples/scenes/hemicylinder.toml";
  std::vector<std::string> sets;
  app.add_option("scene", scene_file, "scene file (TOML)")->capture_default_str();
  app.add_option("--set", sets, "override a scene value: section.key=value")->take_all();
  CLI11_PARSE(app, argc, argv);
  stc::linalg::preferFastBlasKernels();
  // 2. The solve of `stcontact solve` (solveAsTheProgram above).
  if (const int status = solveAsTheProgram(scene_file, sets); status != 0) return status;
  try {
    const stc::Scene scene = stc::readScene(scene_file, sets);
    const stc::Problem problem = stc::buildProblem(scene);
    const stc::ReferenceSolution reference = stc::computeReference(problem, nullptr);
    const stc::SolveInputs inputs{.reference = reference.reference.get()};

    // 3. One option changed at a time (src/options/fas_apriori_options.hpp lists them all).
    const std::vector<Variant> variants = {
        {"as the scene sets it", [](auto&) {}},
        {"on every contact node (zone off)", [](auto& o) { o.zone.enabled = false; }},
        {"coarse space from the last stage", [](auto& o) { o.basis.anticipate = false; }},
        {"5 + 10 modes instead of 15 + 30", [](auto& o) {
           o.basis.modes = 5;
           o.basis.increment_modes = 10;
         }},
        {"coarse step on every node", [](auto& o) { o.fas.coarse_zone = false; }},
    };
    std::printf("\n%-34s %12s %14s %12s %10s\n", "fas-apriori", "relaxations", "sparse solves", "true error",
                "time (s)");
    bool all_agree = true;
    for (const Variant& v : variants) {
      stc::fas::FasAprioriOptions options = scene.solver.fas_apriori;
      v.change(options);
      const stc::SolveSummary s = stc::fas::solveFasApriori(problem, options, inputs).summary;
      std::printf("%-34s %12d %14d %12.2e %10.4f\n", v.what, s.relaxations, s.sparseSolves(),
                  s.error.value_or(-1.0), s.wall_s);
      all_agree = all_agree && s.converged() && s.error && *s.error <= options.fas.stop.tolerance;
    }

    // 4. Every variant converged to the incremental solution: the options change the path, not the
    //    answer.
    return all_agree ? 0 : 2;
  } catch (const stc::InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << '\n';
    return 3;
  }
}
