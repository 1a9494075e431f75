#include "src/mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "src/core/input_error.hpp"

namespace stc {

double Mesh::twiceSignedArea(int e) const {
  const Eigen::Vector2d a = nodes.col(triangles(0, e));
  const Eigen::Vector2d b = nodes.col(triangles(1, e));
  const Eigen::Vector2d c = nodes.col(triangles(2, e));
  return (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
}

const BoundaryGroup& Mesh::group(const std::string& name) const {
  auto it = groups.find(name);
  if (it != groups.end()) return it->second;
  std::ostringstream msg;
  msg << "boundary '" << name << "' is not in the mesh (it has:";
  for (const auto& [key, value] : groups) msg << " '" << key << "'";
  msg << ")";
  throw InputError(msg.str());
}

void Mesh::validate() const {
  if (numElements() == 0) throw InputError("mesh has no triangles");
  for (int e = 0; e < numElements(); ++e)
    for (int a = 0; a < 3; ++a)
      if (triangles(a, e) < 0 || triangles(a, e) >= numNodes())
        throw InputError("element " + std::to_string(e) + " refers to node " +
                         std::to_string(triangles(a, e)) + ", which does not exist");
  double mean = 0.0;
  for (int e = 0; e < numElements(); ++e) mean += std::abs(twiceSignedArea(e));
  mean /= numElements();
  for (int e = 0; e < numElements(); ++e) {
    const double area2 = twiceSignedArea(e);
    if (!(std::abs(area2) > 1e-12 * mean))
      throw InputError("element " + std::to_string(e) + " is degenerate (area " +
                       std::to_string(0.5 * area2) + ")");
    if (area2 < 0)
      throw InputError("element " + std::to_string(e) + " is inverted (clockwise, area " +
                       std::to_string(0.5 * area2) + ")");
  }
  for (const auto& [name, g] : groups)
    for (const auto& edge : g.edges)
      for (int id : edge)
        if (id < 0 || id >= numNodes())
          throw InputError("boundary '" + name + "' refers to node " + std::to_string(id) +
                           ", which does not exist");
}

void Mesh::finalizeGroups() {
  for (auto& [name, g] : groups) {
    for (const auto& edge : g.edges) g.nodes.insert(g.nodes.end(), edge.begin(), edge.end());
    std::sort(g.nodes.begin(), g.nodes.end());
    g.nodes.erase(std::unique(g.nodes.begin(), g.nodes.end()), g.nodes.end());
  }
}

}  // namespace stc
