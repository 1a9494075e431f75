#pragma once
// The rigid-body motions of the body restricted to its free dofs: the near-null space an algebraic
// multigrid needs to coarsen elasticity well (PETSc's MatNullSpaceCreateRigidBody builds the same
// from coordinates when every node has all its dofs free; here a node may have some prescribed).
// In 2D the translations e_x, e_y and the rotation (−y, x); in 3D three translations and the
// rotations e_k × (x − x̄).
#include <Eigen/Core>

#include "stcontact/problem/problem.hpp"

namespace stc {

/// n_free × (3 in 2D, 6 in 3D), columns orthonormal, about the centroid of the nodes.
Eigen::MatrixXd rigidBodyModesOfFreeDofs(const Problem& problem);

}  // namespace stc
