#pragma once
// C A⁻¹ Rᵀ M (C: r × n and R: k × n sparse, M: k × m dense) with as many solves as M has rank:
// with the SVD M = U Σ Vᵀ kept to its numerical rank ρ (σ_i > max(k, m) ε σ_1, what round-off
// cannot tell from zero),
//   C A⁻¹ Rᵀ M = (C A⁻¹ Rᵀ U_ρ) Σ_ρ V_ρᵀ,   ρ ≤ min(k, m) solves,
// half-solves when R reads the factor's trailing dofs alone (SpdSolver::solveFromTrailing). On an
// iterative backend mode i is solved to σ_1/σ_i times its relative residual ρ (at most
// LinearSolverOptions::kLoosestRtol: SpdSolver::solveLoosened): its error, of size σ_i ρ_i, is then
// at most the leading mode's, σ_1 ρ, as for the separated stage's directions (docs/method.md §2,
// "Inexact directions").
// What lifts a solution known on the contact zone to the nodes left out (the far nodes'
// displacements from the zone's force history, src/incremental/reach_zone.hpp and
// pgd/response_basis.hpp) when the zone's operator came from the factor's trailing block with no
// solve: 134 solves for the 201 instants of 801 arc nodes' zone, 82 for 401 × 2001.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "stcontact/linalg/spd_solver.hpp"

namespace stc::linalg {

/// C A⁻¹ Rᵀ M with `factor` of A; adds the solves made (the rank of M) to `solves`.
Eigen::MatrixXd solveThroughRank(const SpdSolver& factor, const Eigen::SparseMatrix<double>& C,
                                 const Eigen::SparseMatrix<double>& R, const Eigen::MatrixXd& M, long& solves);

}  // namespace stc::linalg
