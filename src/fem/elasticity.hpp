#pragma once
// P1 (linear triangle) isotropic elasticity in plane strain or plane stress, unit thickness.
// Dofs are interleaved: u_x of node i at 2i, u_y at 2i + 1.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "stcontact/mesh/tri_mesh.hpp"
#include "stcontact/scene/model_spec.hpp"

namespace stc {

/// Hooke's matrix D (Voigt: xx, yy, xy with engineering shear γ_xy = 2ε_xy).
/// Plane strain: D = E/((1+ν)(1−2ν)) [[1−ν, ν, 0], [ν, 1−ν, 0], [0, 0, (1−2ν)/2]];
/// plane stress: D = E/(1−ν²) [[1, ν, 0], [ν, 1, 0], [0, 0, (1−ν)/2]].
Eigen::Matrix3d hookeMatrix(const MaterialSpec& material, PlaneModel plane);

/// Strain–displacement matrix of element e (3 × 6, constant on the element): ε = B_e u_e.
Eigen::Matrix<double, 3, 6> strainDisplacement(const TriMesh& mesh, int e);

/// Global stiffness K = Σ_e A_e B_eᵀ D B_e (n × n, symmetric positive semi-definite, unconstrained).
Eigen::SparseMatrix<double> assembleStiffness(const TriMesh& mesh, const Eigen::Matrix3d& hooke);

/// Per-element stresses of one displacement field u (size n): rows σ_xx, σ_yy, σ_xy, σ_zz, von Mises.
/// σ_zz = ν(σ_xx + σ_yy) in plane strain, 0 in plane stress.
Eigen::Matrix<double, 5, Eigen::Dynamic> elementStresses(const TriMesh& mesh, const MaterialSpec& material,
                                                          PlaneModel plane, const Eigen::VectorXd& u);

}  // namespace stc
