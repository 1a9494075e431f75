#include "stcontact/mesh/tet_mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <stdexcept>
#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/mesh_checks.hpp"

namespace stc {

double TetMesh::sixSignedVolume(int e) const {
  const Eigen::Vector3d x0 = nodes.col(tets(0, e));
  const Eigen::Vector3d x1 = nodes.col(tets(1, e));
  const Eigen::Vector3d x2 = nodes.col(tets(2, e));
  const Eigen::Vector3d x3 = nodes.col(tets(3, e));
  return (x1 - x0).cross(x2 - x0).dot(x3 - x0);
}

const SurfaceGroup& TetMesh::group(const std::string& name) const { return mesh_checks::findGroup(groups, name); }

void TetMesh::validate() const {
  if (numElements() == 0) throw InputError("mesh has no tetrahedra");
  mesh_checks::checkElementNodeIds(tets, numNodes());
  if (!node_tags.empty() && node_tags.size() != static_cast<std::size_t>(numNodes()))
    throw std::logic_error("mesh: " + std::to_string(node_tags.size()) + " node tags for " + std::to_string(numNodes()) + " nodes");
  mesh_checks::checkGroupNodeIds(groups, &SurfaceGroup::triangles, numNodes());
  mesh_checks::checkElementMeasures(
      numElements(), [this](int e) { return sixSignedVolume(e) / 6.0; }, "volume", "negative volume");
}

void TetMesh::finalizeGroups() { mesh_checks::finalizeGroupNodes(groups, &SurfaceGroup::triangles); }

std::array<int, 3> outwardFace(const TetMesh& mesh, int e, int f) {
  const int* local = kTetFaces[f];
  return {mesh.tets(local[0], e), mesh.tets(local[1], e), mesh.tets(local[2], e)};
}

std::vector<std::array<int, 3>> boundaryTriangles(const TetMesh& mesh) {
  const auto face = [&](int e, int f) { return outwardFace(mesh, e, f); };
  return mesh_checks::facesOfOneElement<3>(mesh.numElements(), 4, face);
}

}  // namespace stc
