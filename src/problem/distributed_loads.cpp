#include "stcontact/problem/distributed_loads.hpp"

#include <algorithm>
#include <array>
#include <map>

#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/facet_measure.hpp"

namespace stc {
namespace {

template <std::size_t N>
std::array<int, N> sorted(std::array<int, N> facet) {
  std::sort(facet.begin(), facet.end());
  return facet;
}

// The mesh's boundary facets, oriented outward (boundaryEdges, boundaryTriangles), by their sorted ids.
template <std::size_t N>
std::map<std::array<int, N>, std::array<int, N>> outwardFacets(const std::vector<std::array<int, N>>& boundary) {
  std::map<std::array<int, N>, std::array<int, N>> outward;
  for (const auto& facet : boundary) outward.emplace(sorted(facet), facet);
  return outward;
}

// The unit outward normal of an outward-oriented facet: (t_y, −t_x) for an edge run with the body on
// its left, the right-hand normal of a face counter-clockwise seen from outside.
Eigen::Vector2d outwardNormal(const Eigen::Matrix2Xd& x, const std::array<int, 2>& edge) {
  const Eigen::Vector2d t = x.col(edge[1]) - x.col(edge[0]);
  return Eigen::Vector2d(t.y(), -t.x()).normalized();
}

Eigen::Vector3d outwardNormal(const Eigen::Matrix3Xd& x, const std::array<int, 3>& t) {
  return (x.col(t[1]) - x.col(t[0])).cross(x.col(t[2]) - x.col(t[0])).normalized();
}

template <class Mesh, std::size_t N>
Eigen::VectorXd pressureOn(const Mesh& mesh, const std::vector<std::array<int, N>>& facets, const std::string& group,
                           const std::vector<std::array<int, N>>& boundary) {
  constexpr int d = static_cast<int>(N);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(d * mesh.nodes.cols());
  if (facets.empty())
    throw InputError("pressure on boundary '" + group + "': the boundary has no " + (d == 3 ? "face" : "edge"));
  const auto outward = outwardFacets(boundary);
  for (const auto& facet : facets) {
    const auto found = outward.find(sorted(facet));
    if (found == outward.end())
      throw InputError("pressure on boundary '" + group + "': a facet of node " + std::to_string(facet[0]) +
                       " is not on the body's boundary");
    const double share = facetMeasure(mesh.nodes, facet) / d;
    const auto n = outwardNormal(mesh.nodes, found->second);
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
    for (int a = 0; a <= d; ++a) f[d * elements(a, e) + componentIndex(component)] += measures[e] / (d + 1);
  return f;
}

}  // namespace

Eigen::VectorXd pressurePattern(const TriMesh& mesh, const std::string& group) {
  return pressureOn(mesh, mesh.group(group).edges, group, boundaryEdges(mesh));
}

Eigen::VectorXd pressurePattern(const TetMesh& mesh, const std::string& group) {
  return pressureOn(mesh, mesh.group(group).triangles, group, boundaryTriangles(mesh));
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
