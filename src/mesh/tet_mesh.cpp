#include "src/mesh/tet_mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "src/core/input_error.hpp"

namespace stc {

double TetMesh::sixSignedVolume(int e) const {
  const Eigen::Vector3d x0 = nodes.col(tets(0, e));
  const Eigen::Vector3d x1 = nodes.col(tets(1, e));
  const Eigen::Vector3d x2 = nodes.col(tets(2, e));
  const Eigen::Vector3d x3 = nodes.col(tets(3, e));
  return (x1 - x0).cross(x2 - x0).dot(x3 - x0);
}

const SurfaceGroup& TetMesh::group(const std::string& name) const {
  auto it = groups.find(name);
  if (it != groups.end()) return it->second;
  std::ostringstream msg;
  msg << "boundary '" << name << "' is not in the mesh (it has:";
  for (const auto& [key, value] : groups) msg << " '" << key << "'";
  msg << ")";
  throw InputError(msg.str());
}

namespace {

void checkNodeIds(const TetMesh& mesh) {
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int a = 0; a < 4; ++a)
      if (mesh.tets(a, e) < 0 || mesh.tets(a, e) >= mesh.numNodes())
        throw InputError("element " + std::to_string(e) + " refers to node " + std::to_string(mesh.tets(a, e)) +
                         ", which does not exist");
  for (const auto& [name, g] : mesh.groups)
    for (const auto& triangle : g.triangles)
      for (int id : triangle)
        if (id < 0 || id >= mesh.numNodes())
          throw InputError("boundary '" + name + "' refers to node " + std::to_string(id) +
                           ", which does not exist");
}

void checkVolumes(const TetMesh& mesh) {
  double mean = 0.0;
  for (int e = 0; e < mesh.numElements(); ++e) mean += std::abs(mesh.sixSignedVolume(e));
  mean /= mesh.numElements();
  for (int e = 0; e < mesh.numElements(); ++e) {
    const double volume6 = mesh.sixSignedVolume(e);
    if (!(std::abs(volume6) > 1e-12 * mean))
      throw InputError("element " + std::to_string(e) + " is degenerate (volume " + std::to_string(volume6 / 6.0) +
                       ")");
    if (volume6 < 0)
      throw InputError("element " + std::to_string(e) + " is inverted (negative volume " +
                       std::to_string(volume6 / 6.0) + ")");
  }
}

}  // namespace

void TetMesh::validate() const {
  if (numElements() == 0) throw InputError("mesh has no tetrahedra");
  checkNodeIds(*this);
  checkVolumes(*this);
}

void TetMesh::finalizeGroups() {
  for (auto& [name, g] : groups) {
    for (const auto& triangle : g.triangles) g.nodes.insert(g.nodes.end(), triangle.begin(), triangle.end());
    std::sort(g.nodes.begin(), g.nodes.end());
    g.nodes.erase(std::unique(g.nodes.begin(), g.nodes.end()), g.nodes.end());
  }
}

std::vector<std::array<int, 3>> boundaryTriangles(const TetMesh& mesh) {
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  std::map<std::array<int, 3>, std::array<int, 3>> once;  // sorted ids → oriented face
  for (int e = 0; e < mesh.numElements(); ++e)
    for (const auto& face : kFaces) {
      const std::array<int, 3> oriented{mesh.tets(face[0], e), mesh.tets(face[1], e), mesh.tets(face[2], e)};
      std::array<int, 3> key = oriented;
      std::sort(key.begin(), key.end());
      auto [it, inserted] = once.emplace(key, oriented);
      if (!inserted) once.erase(it);  // an interior face, shared by two elements
    }
  std::vector<std::array<int, 3>> faces;
  faces.reserve(once.size());
  for (const auto& [key, oriented] : once) faces.push_back(oriented);
  return faces;
}

}  // namespace stc
