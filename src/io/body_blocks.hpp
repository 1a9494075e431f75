#pragma once
// One ParaView block per body when the mesh holds several (two bodies in contact, docs/two_bodies.md):
// each body's nodes and elements as a grid of its own, written as one part of each frame, so that
// ParaView's PVD reader shows the bodies as the blocks of one multiblock dataset (solution.pvd lists
// every frame's files with part = the body; docs/interface.md, "solution.pvd and vtu/").
#include <ostream>
#include <vector>

#include "stcontact/io/vtu_writer.hpp"
#include "stcontact/mesh/body_mesh.hpp"

namespace stc {

struct BodyBlock {
  std::vector<int> nodes;     ///< the whole mesh's ids of the body's nodes, increasing
  std::vector<int> elements;  ///< the whole mesh's ids of the body's elements, increasing
  VtuGrid grid;               ///< the body alone, its nodes and elements renumbered in these orders
};

/// A block per connected part of the mesh, `part_of` each node's (mesh/connected_parts.hpp,
/// partOfNodes), numbered as the parts.
std::vector<BodyBlock> bodyBlocks(const BodyMesh& body, const std::vector<int>& part_of, FieldPrecision precision);

/// The block's document of a frame: the columns of `points` at its nodes, of `cells` at its elements.
void writeBlock(std::ostream& out, const BodyBlock& block, const std::vector<PointField>& points,
                const std::vector<CellField>& cells);

}  // namespace stc
