// One ParaView block per body (src/io/body_blocks.hpp): the blocks partition the mesh's nodes and
// elements, each is a grid of its own with its nodes renumbered, and its document carries the
// frame's fields at its nodes and elements.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "fixtures/seed_scene.hpp"
#include "fixtures/two_bodies_scene.hpp"
#include "io/vtu_reading.hpp"
#include "stcontact/io/body_blocks.hpp"
#include "stcontact/mesh/connected_parts.hpp"
#include "stcontact/problem/problem.hpp"

namespace stc {
namespace {

TEST(BodyBlocks, TwoBodiesMakeTwoBlocksThatPartitionTheMesh) {
  const Problem pair = buildProblem(test::mirroredPair(test::seedScene(21, 3)));
  const TriMesh& mesh = std::get<TriMesh>(pair.body);
  const std::vector<BodyBlock> blocks = bodyBlocks(pair.body, partOfNodes(pair.body), FieldPrecision::Float64);
  ASSERT_EQ(blocks.size(), 2u);
  std::vector<int> nodes = blocks[0].nodes, elements = blocks[0].elements;
  nodes.insert(nodes.end(), blocks[1].nodes.begin(), blocks[1].nodes.end());
  elements.insert(elements.end(), blocks[1].elements.begin(), blocks[1].elements.end());
  std::sort(nodes.begin(), nodes.end());
  std::sort(elements.begin(), elements.end());
  EXPECT_EQ(static_cast<int>(nodes.size()), mesh.numNodes());
  EXPECT_EQ(std::adjacent_find(nodes.begin(), nodes.end()), nodes.end());
  EXPECT_EQ(static_cast<int>(elements.size()), mesh.numElements());
  EXPECT_EQ(std::adjacent_find(elements.begin(), elements.end()), elements.end());
  EXPECT_EQ(blocks[0].nodes.size(), blocks[1].nodes.size());  // the mirror image
  for (int e : blocks[1].elements)  // every node of a block's element is the block's
    for (int a = 0; a < 3; ++a)
      EXPECT_TRUE(std::binary_search(blocks[1].nodes.begin(), blocks[1].nodes.end(), mesh.triangles(a, e)));
}

// A field equal to each node's (and element's) id comes out of the block as the block's own ids.
TEST(BodyBlocks, ABlocksDocumentCarriesTheFieldsAtItsNodesAndElements) {
  const Problem pair = buildProblem(test::mirroredPair(test::seedScene(21, 3)));
  const std::vector<BodyBlock> blocks = bodyBlocks(pair.body, partOfNodes(pair.body), FieldPrecision::Float64);
  const int n = pair.numNodes(), e = numElements(pair.body);
  const Eigen::MatrixXd node_ids = Eigen::RowVectorXd::LinSpaced(n, 0, n - 1);
  const Eigen::MatrixXd element_ids = Eigen::RowVectorXd::LinSpaced(e, 0, e - 1);
  const BodyBlock& block = blocks[1];
  std::ostringstream out;
  writeBlock(out, block, {{"id", node_ids}}, {{"element", element_ids}});
  const iotest::VtuFile file = iotest::readVtu(out.str());
  const std::string piece = "<Piece NumberOfPoints=\"" + std::to_string(block.nodes.size()) + "\" NumberOfCells=\"" +
                            std::to_string(block.elements.size()) + "\">";
  EXPECT_NE(file.xml.find(piece), std::string::npos);
  const std::vector<double>& ids = file.array("PointData", "id").values;
  ASSERT_EQ(ids.size(), block.nodes.size());
  for (size_t j = 0; j < ids.size(); ++j) EXPECT_EQ(ids[j], block.nodes[j]);
  const std::vector<double>& cells = file.array("CellData", "element").values;
  ASSERT_EQ(cells.size(), block.elements.size());
  for (size_t j = 0; j < cells.size(); ++j) EXPECT_EQ(cells[j], block.elements[j]);
}

}  // namespace
}  // namespace stc
