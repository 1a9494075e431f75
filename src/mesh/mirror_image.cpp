#include "stcontact/mesh/mirror_image.hpp"

#include <string>
#include <type_traits>

#include "stcontact/core/input_error.hpp"

namespace stc {
namespace {

template <class Mesh>
Mesh mirrored(const Mesh& body, double gap) {
  const Eigen::Index d = body.nodes.rows(), n = body.nodes.cols(), ne = body.numElements();
  const double plane = body.nodes.row(d - 1).minCoeff() - 0.5 * gap;
  Mesh pair;
  pair.nodes.resize(d, 2 * n);
  pair.nodes.leftCols(n) = body.nodes;
  pair.nodes.rightCols(n) = body.nodes;
  pair.nodes.row(d - 1).tail(n) = (2.0 * plane - body.nodes.row(d - 1).array()).matrix();
  auto& elements = elementNodes(pair);
  const auto& source = elementNodes(body);
  elements.resize(source.rows(), 2 * ne);
  elements.leftCols(ne) = source;
  elements.rightCols(ne) = source.array() + static_cast<int>(n);
  elements.row(0).tail(ne).swap(elements.row(1).tail(ne));  // a reflection reverses the orientation
  pair.groups = body.groups;
  for (const auto& [name, group] : body.groups) {
    const std::string image = kMirrorPrefix + name;
    if (body.groups.count(image) > 0)
      throw InputError("mesh.mirror_gap: the mesh already has a group '" + image + "' (the image's groups are named '" +
                       kMirrorPrefix + "' + the body's)");
    auto& copy = pair.groups[image] = group;
    for (int& node : copy.nodes) node += static_cast<int>(n);
    if constexpr (std::is_same_v<Mesh, TriMesh>) {
      for (auto& edge : copy.edges) edge = {edge[1] + static_cast<int>(n), edge[0] + static_cast<int>(n)};
    } else {
      for (auto& t : copy.triangles) t = {t[1] + static_cast<int>(n), t[0] + static_cast<int>(n), t[2] + static_cast<int>(n)};
    }
  }
  pair.validate();
  return pair;
}

}  // namespace

BodyMesh withMirrorImage(const BodyMesh& body, double gap) {
  return std::visit([&](const auto& mesh) { return BodyMesh(mirrored(mesh, gap)); }, body);
}

}  // namespace stc
