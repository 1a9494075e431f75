#pragma once
// P1 (linear tetrahedron) isotropic linear elasticity in three dimensions.
// Dofs are interleaved: u_x of node i at 3i, u_y at 3i + 1, u_z at 3i + 2.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "stcontact/mesh/tet_mesh.hpp"
#include "stcontact/scene/model_spec.hpp"

namespace stc {

/// Hooke's matrix D (Voigt: xx, yy, zz, yz, xz, xy with engineering shears γ_ij = 2ε_ij):
/// D = E/((1+ν)(1−2ν)) [[1−ν, ν, ν, 0, 0, 0], [ν, 1−ν, ν, 0, 0, 0], [ν, ν, 1−ν, 0, 0, 0],
///                      [0, 0, 0, (1−2ν)/2, 0, 0], [0, 0, 0, 0, (1−2ν)/2, 0], [0, 0, 0, 0, 0, (1−2ν)/2]]
/// (Zienkiewicz & Taylor, The Finite Element Method vol. 1, "Three-dimensional stress analysis").
Eigen::Matrix<double, 6, 6> hookeMatrix3d(const MaterialSpec& material);

/// Strain–displacement matrix of element e (6 × 12, constant on the element): ε = B_e u_e.
Eigen::Matrix<double, 6, 12> strainDisplacement(const TetMesh& mesh, int e);

/// Global stiffness K = Σ_e V_e B_eᵀ D B_e (3n × 3n, symmetric positive semi-definite, unconstrained).
Eigen::SparseMatrix<double> assembleStiffness(const TetMesh& mesh, const Eigen::Matrix<double, 6, 6>& hooke);

/// Per-element stresses of one displacement field u (size 3n): rows σ_xx, σ_yy, σ_zz, σ_yz, σ_xz,
/// σ_xy, von Mises √(½[(σ_xx−σ_yy)² + (σ_yy−σ_zz)² + (σ_zz−σ_xx)²] + 3(σ_yz² + σ_xz² + σ_xy²)).
Eigen::Matrix<double, 7, Eigen::Dynamic> elementStresses(const TetMesh& mesh, const MaterialSpec& material,
                                                          const Eigen::VectorXd& u);

}  // namespace stc
