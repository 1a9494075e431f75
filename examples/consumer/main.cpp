// Description: the smallest outside program linking the installed stcontact library.
// Sample run:  consumer examples/scenes/hemicylinder.toml
// 1. read and validate a scene, 2. assemble the problem, 3. solve it with LATIN on a short grid,
// 4. print the sizes and the final total normal force.
#include <iostream>

#include "stcontact/latin/latin_solver.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene_reader.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: consumer SCENE.toml\n";
    return 1;
  }
  const stc::Scene scene = stc::readScene(argv[1], {"time.steps=21", "mesh.arc_nodes=21"});
  const stc::Problem problem = stc::buildProblem(scene);
  stc::latin::LatinOptions options;
  options.stop.tolerance = 1e-4;
  const stc::SolveResult result = stc::latin::solveLatin(problem, options);
  // Contact node i owns d rows from d i on, the normal one first (src/spacetime/interface_history.hpp).
  const int d = problem.contact.dimension;
  const Eigen::VectorXd last = result.interface.lambda.col(problem.numSteps() - 1);
  const double normal_force = last(Eigen::seq(0, Eigen::last, d)).sum();
  std::cout << "dofs " << problem.numDofs() << ", contact nodes " << problem.contact.size() << ", steps "
            << problem.numSteps() << ", " << stc::toString(result.summary.termination) << " after "
            << result.summary.iterations << " iterations, final normal force " << normal_force << "\n";
  return result.summary.converged() ? 0 : 2;
}
