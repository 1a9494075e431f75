#pragma once
// The FAS tests' reference problem: the seed scene on 31 contact nodes × 41 instants (κ = 3), its
// incremental solution and the converged free displacements, built once per test program.
#include <Eigen/Core>

#include "fixtures/seed_scene.hpp"
#include "stcontact/incremental/condensed_interface.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/linalg/dense_decompositions.hpp"
#include "stcontact/linalg/backends/cholmod_factor.hpp"
#include "stcontact/operators/displacement.hpp"

namespace stc::test {

struct SeedFas {
  Problem problem;
  SolveResult reference;
  Eigen::MatrixXd u_ref;  ///< converged free displacements, n_free × m
  SeedFas() : problem(make()), reference(solveIncremental(problem)) {
    const CholmodFactor K(problem.stiffness_free, "K");
    u_ref = freeDisplacements(problem, K, reference.interface.lambda);
  }
  static Problem make() {
    Scene scene = seedScene(31, 41);
    scene.search_direction.scale = 3.0;
    return buildProblem(scene);
  }
  /// The leading `count` left singular vectors of u_ref.
  Eigen::MatrixXd leadingModes(int count) const {
    using namespace linalg;
    return singularValueDecomposition(u_ref, SvdMethod::divide_and_conquer, kThinU).U.leftCols(count);
  }
};

inline const SeedFas& seedFas() {
  static const SeedFas f;
  return f;
}

}  // namespace stc::test
