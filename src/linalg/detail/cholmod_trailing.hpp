#pragma once
// The trailing block of a CHOLMOD factor, for SpdSolver's factor with given dofs ordered last
// (src/linalg/backends/cholmod_factor.hpp). With the dofs J eliminated after every other dof I, the trailing |J| × |J|
// block of L is the Cholesky factor of the Schur complement
//   S = A_JJ − A_JI A_II⁻¹ A_IJ = L_JJ L_JJᵀ,   and   (A⁻¹)_JJ = S⁻¹
// (the block inverse; e.g. Golub & Van Loan, Matrix Computations, 4th ed., §3.2.10), so the
// factorisation that solves A also gives A⁻¹ on J, with no solve.
#include <cholmod.h>

#include <Eigen/Core>
#include <vector>

namespace stc::linalg {

/// `analysed`'s fill-reducing permutation (L->Perm of cholmod_analyze) with the dofs of `trailing`
/// taken out and appended at the end, in the order given (the others keep their relative order).
std::vector<int> orderingWithTrailing(const cholmod_factor& analysed, const std::vector<int>& trailing);

/// The trailing `count` × `count` block of a numeric LLᵀ factor (supernodal, or simplicial LLᵀ),
/// dense, lower triangular, rows and columns in the factor's (permuted) order.
Eigen::MatrixXd trailingBlock(const cholmod_factor& L, int count);

}  // namespace stc::linalg
