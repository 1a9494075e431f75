#pragma once
// Residual vectors (RES) of seed §4.3: N_res vectors that span what the fixed basis misses of the
// current displacement history ũ, i.e. the leading left singular directions of
// R = ũ − Y (Yᵀ A ũ) (the A-orthogonal complement of ũ's projection on an A-orthonormal Y),
// found by a randomized range finder (fixed seed: deterministic) — a compression of the iterate,
// not an SVD of a converged solution.
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace stc::fas {

/// `fixed` must be A-orthonormal (or empty). Returns n_free × min(count, rank of R) vectors.
Eigen::MatrixXd residualVectors(const Eigen::MatrixXd& u_tilde, const Eigen::MatrixXd& fixed,
                                const Eigen::SparseMatrix<double>& A, int count);

/// The leading min(count, rank R) left singular directions of R (orthonormal columns), by the
/// randomized range finder that `residualVectors` applies to its R.
Eigen::MatrixXd rangeOf(const Eigen::MatrixXd& R, int count);

}  // namespace stc::fas
