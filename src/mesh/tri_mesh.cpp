#include "stcontact/mesh/tri_mesh.hpp"

#include <stdexcept>
#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/mesh_checks.hpp"

namespace stc {

double TriMesh::twiceSignedArea(int e) const {
  const Eigen::Vector2d a = nodes.col(triangles(0, e));
  const Eigen::Vector2d b = nodes.col(triangles(1, e));
  const Eigen::Vector2d c = nodes.col(triangles(2, e));
  return (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
}

const BoundaryGroup& TriMesh::group(const std::string& name) const { return mesh_checks::findGroup(groups, name); }

void TriMesh::validate() const {
  if (numElements() == 0) throw InputError("mesh has no triangles");
  mesh_checks::checkElementNodeIds(triangles, numNodes());
  if (!node_tags.empty() && node_tags.size() != static_cast<std::size_t>(numNodes()))
    throw std::logic_error("mesh: " + std::to_string(node_tags.size()) + " node tags for " + std::to_string(numNodes()) + " nodes");
  mesh_checks::checkElementMeasures(
      numElements(), [this](int e) { return 0.5 * twiceSignedArea(e); }, "area", "clockwise, area");
  mesh_checks::checkGroupNodeIds(groups, &BoundaryGroup::edges, numNodes());
}

void TriMesh::finalizeGroups() { mesh_checks::finalizeGroupNodes(groups, &BoundaryGroup::edges); }

std::vector<std::array<int, 2>> boundaryEdges(const TriMesh& mesh) {
  return mesh_checks::facesOfOneElement<2>(mesh.numElements(), 3, [&](int e, int a) {
    return std::array<int, 2>{mesh.triangles(a, e), mesh.triangles((a + 1) % 3, e)};
  });
}

}  // namespace stc
