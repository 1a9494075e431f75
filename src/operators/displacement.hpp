#pragma once
// The body's displacement from its contact forces, u(λ): at every instant the body is in
// equilibrium under its loads and the interface forces (docs/method.md §1, seed eq. (1)),
//   K_ff u_free(t_k) = f(t_k) + Bᵀ λ(t_k),
// then the prescribed values u_d(t_k) put back on their dofs (Problem::fullDisplacement). Every
// caller that rebuilds a displacement from forces comes here, with the factor of K_ff its run
// prepared once (prepared_operators.hpp).
#include <Eigen/Core>

#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/problem/problem.hpp"

namespace stc {

/// u_free(t_k) for every instant (n_free × m): one multi-right-hand-side solve on every thread.
Eigen::MatrixXd freeDisplacements(const Problem& problem, const SpdSolver& stiffness_free, const Eigen::MatrixXd& lambda);

/// The full displacements (n × m, prescribed dofs included, in the obstacle's frame).
Eigen::MatrixXd fullDisplacements(const Problem& problem, const SpdSolver& stiffness_free, const Eigen::MatrixXd& lambda);

/// u_free(t_k) of the one instant k from λ(t_k) = `lambda_k` (d n_C), solved with `workspace`: what
/// a writer of frames calls from several threads, one workspace each.
Eigen::VectorXd freeDisplacementAt(const Problem& problem, const SpdSolver& stiffness_free,
                                   const Eigen::VectorXd& lambda_k, int k, SpdSolver::Workspace& workspace);

}  // namespace stc
