// Description
//   A posteriori vs a priori coarse bases (design card; METHOD.md §4–5): on one scene, runs
//   `latin`, `latin-pgd`, `fas-aposteriori`, `fas-apriori` (and `incremental`, the reference point),
//   and prints per strategy the relaxations, sparse solves and wall time to reach true error 1e-2,
//   1e-4, 1e-6. Work in progress (issue 6).
// Sample run
//   build/bin/compare_bases examples/scenes/hemicylinder.toml
#include <chrono>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "fas/solve_by_name.hpp"
#include "src/core/input_error.hpp"
#include "src/scene/scene_reader.hpp"
#include "src/solver/condensed_interface.hpp"
#include "src/solver/incremental_solver.hpp"

int main(int argc, char** argv) {
  try {
    std::vector<std::string> overrides;
    std::string scene_file = argc > 1 ? argv[1] : "examples/scenes/hemicylinder.toml";
    for (int i = 2; i + 1 < argc; i += 2)
      if (std::string(argv[i]) == "--set") overrides.push_back(argv[i + 1]);
    const stc::Scene scene = stc::readScene(scene_file, overrides);
    const stc::Problem problem = stc::buildProblem(scene);
    const stc::SolveResult ref = stc::solveIncremental(problem);
    const stc::SpdFactor K(problem.stiffness_free, "K_ff");
    const auto condensed = stc::CondensedInterface::build(problem, K);
    const stc::ErrorReference reference(problem, K, condensed.delassus, ref.interface.lambda);
    for (const std::string name : {"latin", "latin-pgd", "fas-aposteriori", "fas-apriori"}) {
      stc::fas::StrategyInputs in;
      in.reference = &reference;
      in.converged_lambda = &ref.interface.lambda;
      const auto r = stc::fas::solveByName(name, problem, scene.solver, in);
      std::cout << name << ": " << toString(r.summary.termination) << " relax " << r.summary.relaxations
                << " err " << r.summary.error.value_or(-1) << " wall " << r.summary.wall_s << "\n";
      for (double target : {1e-2, 1e-4, 1e-6})
        for (const auto& h : r.summary.history)
          if (h.error && *h.error <= target) {
            std::cout << "   to " << target << ": relax " << h.relaxations << " solves " << h.sparse_solves
                      << " rank " << h.rank << " wall " << h.wall_s << "\n";
            break;
          }
    }
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
