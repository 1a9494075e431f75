#include "stcontact/problem/distributed_loads.hpp"

#include <algorithm>
#include <array>
#include <map>

#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/facet_measure.hpp"

namespace stc {
namespace {

int indexOf(Component c) { return c == Component::X ? 0 : c == Component::Y ? 1 : 2; }

template <std::size_t N>
std::array<int, N> sorted(std::array<int, N> facet) {
  std::sort(facet.begin(), facet.end());
  return facet;
}

// For every facet of every element (its nodes sorted), the element's node opposite it: the side
// the body lies on.
template <std::size_t N, class Elements>
std::map<std::array<int, N>, int> oppositeNodes(const Elements& elements) {
  std::map<std::array<int, N>, int> opposite;
  for (Eigen::Index e = 0; e < elements.cols(); ++e)
    for (int skip = 0; skip <= static_cast<int>(N); ++skip) {
      std::array<int, N> facet{};
      std::size_t k = 0;
      for (int a = 0; a <= static_cast<int>(N); ++a)
        if (a != skip) facet[k++] = elements(a, e);
      opposite[sorted(facet)] = elements(skip, e);
    }
  return opposite;
}

Eigen::Vector2d facetNormal(const Eigen::Matrix2Xd& x, const std::array<int, 2>& edge) {
  const Eigen::Vector2d t = x.col(edge[1]) - x.col(edge[0]);
  return Eigen::Vector2d(t.y(), -t.x()).normalized();
}

Eigen::Vector3d facetNormal(const Eigen::Matrix3Xd& x, const std::array<int, 3>& t) {
  return (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0])).normalized();
}

template <class Mesh, std::size_t N>
Eigen::VectorXd pressureOn(const Mesh& mesh, const std::vector<std::array<int, N>>& facets, const std::string& group,
                           const std::map<std::array<int, N>, int>& opposite) {
  constexpr int d = static_cast<int>(N);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(d * mesh.nodes.cols());
  if (facets.empty())
    throw InputError("pressure on boundary '" + group + "': the boundary has no " + (d == 3 ? "face" : "edge"));
  for (const auto& facet : facets) {
    const auto found = opposite.find(sorted(facet));
    if (found == opposite.end())
      throw InputError("pressure on boundary '" + group + "': a facet of node " + std::to_string(facet[0]) +
                       " belongs to no element");
    auto n = facetNormal(mesh.nodes, facet);
    if (n.dot(mesh.nodes.col(found->second) - mesh.nodes.col(facet[0])) > 0.0) n = -n;  // outward
    const double share = facetMeasure(mesh.nodes, facet) / d;
    for (int node : facet) f.segment(d * node, d) -= share * n;
  }
  return f;
}

template <class Mesh>
Eigen::VectorXd bodyForceOn(const Mesh& mesh, const Eigen::MatrixXi& elements, const Eigen::VectorXd& measures,
                            Component component) {
  const int d = static_cast<int>(mesh.nodes.rows());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(d * mesh.nodes.cols());
  for (Eigen::Index e = 0; e < elements.cols(); ++e)
    for (int a = 0; a <= d; ++a) f[d * elements(a, e) + indexOf(component)] += measures[e] / (d + 1);
  return f;
}

}  // namespace

Eigen::VectorXd pressurePattern(const TriMesh& mesh, const std::string& group) {
  return pressureOn(mesh, mesh.group(group).edges, group, oppositeNodes<2>(mesh.triangles));
}

Eigen::VectorXd pressurePattern(const TetMesh& mesh, const std::string& group) {
  return pressureOn(mesh, mesh.group(group).triangles, group, oppositeNodes<3>(mesh.tets));
}

Eigen::VectorXd bodyForcePattern(const TriMesh& mesh, Component component) {
  Eigen::VectorXd area(mesh.numElements());
  for (int e = 0; e < mesh.numElements(); ++e) area[e] = 0.5 * std::abs(mesh.twiceSignedArea(e));
  return bodyForceOn(mesh, mesh.triangles, area, component);
}

Eigen::VectorXd bodyForcePattern(const TetMesh& mesh, Component component) {
  Eigen::VectorXd volume(mesh.numElements());
  for (int e = 0; e < mesh.numElements(); ++e) volume[e] = std::abs(mesh.sixSignedVolume(e)) / 6.0;
  return bodyForceOn(mesh, mesh.tets, volume, component);
}

}  // namespace stc
