#pragma once
// The body a problem is posed on (docs/method.md §1): a mesh of P1 triangles in 2D (TriMesh) or of
// P1 tetrahedra in 3D (TetMesh), one variant. Code that is the same in both dimensions visits it
// (std::visit over the overloads of fem/, contact/, io/, each written for its element); code for
// one dimension asks for its mesh by type (std::get<TriMesh>).
#include <Eigen/Core>
#include <string>
#include <variant>
#include <vector>

#include "stcontact/mesh/tet_mesh.hpp"
#include "stcontact/mesh/tri_mesh.hpp"

namespace stc {

using BodyMesh = std::variant<TriMesh, TetMesh>;

/// 2 for triangles, 3 for tetrahedra.
inline int dimensionOf(const BodyMesh& body) { return std::holds_alternative<TetMesh>(body) ? 3 : 2; }

inline int numNodes(const BodyMesh& body) {
  return std::visit([](const auto& mesh) { return mesh.numNodes(); }, body);
}

/// The number a user knows each node by: the mesh file's tag (Gmsh), or its position from 1 for a
/// mesh made here.
inline std::vector<long long> nodeTags(const BodyMesh& body) {
  return std::visit(
      [](const auto& mesh) {
        if (!mesh.node_tags.empty()) return mesh.node_tags;
        std::vector<long long> tags(static_cast<std::size_t>(mesh.numNodes()));
        for (std::size_t i = 0; i < tags.size(); ++i) tags[i] = static_cast<long long>(i) + 1;
        return tags;
      },
      body);
}

inline int numElements(const BodyMesh& body) {
  return std::visit([](const auto& mesh) { return mesh.numElements(); }, body);
}

/// Node coordinates, d × numNodes.
inline Eigen::MatrixXd nodePositions(const BodyMesh& body) {
  return std::visit([](const auto& mesh) { return Eigen::MatrixXd(mesh.nodes); }, body);
}

/// Throws InputError (listing the groups the mesh has) unless the boundary group `name` exists.
inline void requireGroup(const BodyMesh& body, const std::string& name) {
  std::visit([&](const auto& mesh) { mesh.group(name); }, body);
}

}  // namespace stc
