#pragma once
// Nodal force patterns of distributed loads on P1 meshes (per unit value of their history):
//   pressure p on a boundary group: each facet (edge, triangle) of measure |f| and outward unit
//     normal n_f gives −p n_f |f| / k to each of its k nodes (the consistent load of a constant
//     traction on linear elements); n_f from the facet as the mesh's boundary orients it
//     (boundaryEdges, boundaryTriangles: the body on its inner side);
//   body force b along a component: each element of measure |e| gives b |e| / (d + 1) to each of
//     its d + 1 nodes (Zienkiewicz & Taylor, The Finite Element Method, vol. 1, §6.2: the consistent
//     load of a constant body force on a linear simplex).
// Patterns are full fields (d entries per node).
#include <Eigen/Core>
#include <string>

#include "stcontact/mesh/tet_mesh.hpp"
#include "stcontact/mesh/tri_mesh.hpp"
#include "stcontact/scene/model_spec.hpp"

namespace stc {

/// The nodal forces of a unit pressure on `group` (2D: per unit thickness). Throws InputError when
/// the group has no facet, or a facet that is not on the body's boundary.
Eigen::VectorXd pressurePattern(const TriMesh& mesh, const std::string& group);
Eigen::VectorXd pressurePattern(const TetMesh& mesh, const std::string& group);

/// The nodal forces of a unit body force along `component` on every element.
Eigen::VectorXd bodyForcePattern(const TriMesh& mesh, Component component);
Eigen::VectorXd bodyForcePattern(const TetMesh& mesh, Component component);

}  // namespace stc
