#pragma once
// Verification of a reduced basis against another (docs/method.md §5: "The SVD is used only to check the
// a priori basis: principal angles, projection error of the converged solution on it").
// Inner product: an SPD matrix M (e.g. K_ff, the energy of the free displacements); bases are made
// M-orthonormal by linalg::orthonormalIn (src/linalg/dense_decompositions.hpp).
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace stc::pgd {

/// Cosines of the principal angles between span X and span Y in the M product (Björck & Golub
/// 1973: singular values of QxᵀM Qy), largest first; min(rank X, rank Y) of them.
Eigen::VectorXd principalCosines(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Y,
                                 const Eigen::SparseMatrix<double>& M);

/// ‖U − Π U‖_M / ‖U‖_M over all columns, Π the M-orthogonal projection on span Y.
double projectionError(const Eigen::MatrixXd& U, const Eigen::MatrixXd& Y, const Eigen::SparseMatrix<double>& M);

}  // namespace stc::pgd
