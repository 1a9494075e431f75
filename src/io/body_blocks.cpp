#include "stcontact/io/body_blocks.hpp"

#include <algorithm>
#include <utility>
#include <variant>

namespace stc {
namespace {

// The mesh of one part: its nodes in increasing order, its elements (those whose first node is in
// it) renumbered; no boundary groups (the grid does not need them).
template <class Mesh>
Mesh partMesh(const Mesh& mesh, const std::vector<int>& part_of, int part, std::vector<int>& nodes, std::vector<int>& elements) {
  std::vector<int> renumbered(part_of.size(), -1);
  for (int node = 0; node < static_cast<int>(part_of.size()); ++node)
    if (part_of[static_cast<size_t>(node)] == part) {
      renumbered[static_cast<size_t>(node)] = static_cast<int>(nodes.size());
      nodes.push_back(node);
    }
  const auto& connectivity = elementNodes(mesh);
  for (int e = 0; e < connectivity.cols(); ++e)
    if (part_of[static_cast<size_t>(connectivity(0, e))] == part) elements.push_back(e);
  Mesh block;
  block.nodes = mesh.nodes(Eigen::all, nodes);
  auto& block_elements = elementNodes(block);
  block_elements.resize(connectivity.rows(), static_cast<Eigen::Index>(elements.size()));
  for (size_t j = 0; j < elements.size(); ++j)
    for (Eigen::Index a = 0; a < connectivity.rows(); ++a)
      block_elements(a, static_cast<Eigen::Index>(j)) = renumbered[static_cast<size_t>(connectivity(a, elements[j]))];
  return block;
}

template <class Field>
std::vector<Field> columnsAt(const std::vector<Field>& fields, const std::vector<int>& columns) {
  std::vector<Field> restricted;
  for (const Field& field : fields) restricted.push_back({field.name, field.values(Eigen::all, columns), field.kind});
  return restricted;
}

}  // namespace

std::vector<BodyBlock> bodyBlocks(const BodyMesh& body, const std::vector<int>& part_of, FieldPrecision precision) {
  const int parts = part_of.empty() ? 0 : *std::max_element(part_of.begin(), part_of.end()) + 1;
  std::vector<BodyBlock> blocks;
  for (int part = 0; part < parts; ++part)
    std::visit(
        [&](const auto& mesh) {
          std::vector<int> nodes, elements;
          const auto block = partMesh(mesh, part_of, part, nodes, elements);
          blocks.push_back({std::move(nodes), std::move(elements), VtuGrid(block, precision)});
        },
        body);
  return blocks;
}

void writeBlock(std::ostream& out, const BodyBlock& block, const std::vector<PointField>& points,
                const std::vector<CellField>& cells) {
  block.grid.write(out, columnsAt(points, block.nodes), columnsAt(cells, block.elements));
}

}  // namespace stc
