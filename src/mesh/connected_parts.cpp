#include "stcontact/mesh/connected_parts.hpp"

#include <numeric>

namespace stc {

std::vector<int> partOfNodes(const BodyMesh& body) {
  const int n = numNodes(body);
  std::vector<int> root(static_cast<std::size_t>(n));  // union-find over the elements
  std::iota(root.begin(), root.end(), 0);
  const auto find = [&](int a) {
    while (root[a] != a) a = root[a] = root[root[a]];
    return a;
  };
  std::visit([&](const auto& mesh) {
    const auto& elements = elementNodes(mesh);
    for (Eigen::Index e = 0; e < elements.cols(); ++e)
      for (Eigen::Index a = 1; a < elements.rows(); ++a) root[find(elements(a, e))] = find(elements(0, e));
  }, body);
  std::vector<int> part_of_root(static_cast<std::size_t>(n), -1), part(static_cast<std::size_t>(n));
  int parts = 0;
  for (int i = 0; i < n; ++i) {
    int& p = part_of_root[find(i)];
    if (p < 0) p = parts++;
    part[i] = p;
  }
  return part;
}

std::vector<std::vector<int>> connectedParts(const BodyMesh& body) {
  const std::vector<int> part = partOfNodes(body);
  std::vector<std::vector<int>> parts;
  for (int i = 0; i < static_cast<int>(part.size()); ++i) {
    if (part[i] >= static_cast<int>(parts.size())) parts.resize(part[i] + 1);
    parts[part[i]].push_back(i);
  }
  return parts;
}

}  // namespace stc
