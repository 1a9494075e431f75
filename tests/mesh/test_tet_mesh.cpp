// Tetrahedron mesh: signed volume, validation messages, groups and boundary faces.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "mesh/two_tets.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/tet_mesh.hpp"

using stc::test::twoTets;

namespace {

std::string messageOf(const stc::TetMesh& mesh) {
  try {
    mesh.validate();
  } catch (const stc::InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST(TetMesh, SignedVolumeIsPositiveForTheRightHandedOrder) {
  const stc::TetMesh mesh = twoTets();
  EXPECT_DOUBLE_EQ(mesh.sixSignedVolume(0), 1.0);
  EXPECT_DOUBLE_EQ(mesh.sixSignedVolume(1), 1.0);
  EXPECT_EQ(mesh.numDofs(), 15);
  EXPECT_EQ(mesh.numElements(), 2);
  EXPECT_NO_THROW(mesh.validate());
}

TEST(TetMesh, ValidateNamesTheInvertedTetrahedron) {
  stc::TetMesh mesh = twoTets();
  std::swap(mesh.tets(1, 1), mesh.tets(2, 1));
  EXPECT_EQ(messageOf(mesh), "element 1 is inverted (negative volume -0.166667)");
}

TEST(TetMesh, ValidateNamesTheFlatTetrahedron) {
  stc::TetMesh mesh = twoTets();
  mesh.nodes.col(4) << 0.0, 0.5, 0.5;  // on the face x = 0: the second element is flat
  EXPECT_EQ(messageOf(mesh), "element 1 is degenerate (volume 0)");
}

TEST(TetMesh, ValidateNamesAMissingNode) {
  stc::TetMesh mesh = twoTets();
  mesh.tets(3, 1) = 7;
  EXPECT_EQ(messageOf(mesh), "element 1 refers to node 7, which does not exist");
  mesh = twoTets();
  mesh.groups["top"].triangles.push_back({0, 1, 9});
  EXPECT_EQ(messageOf(mesh), "boundary 'top' refers to node 9, which does not exist");
}

TEST(TetMesh, GroupListsTheGroupsWhenMissing) {
  stc::TetMesh mesh = twoTets();
  mesh.groups["top"].triangles.push_back({3, 1, 2});
  mesh.groups["contact"].triangles.push_back({0, 2, 1});
  mesh.finalizeGroups();
  EXPECT_EQ(mesh.group("top").nodes, (std::vector<int>{1, 2, 3}));
  try {
    mesh.group("bottom");
    FAIL() << "no exception";
  } catch (const stc::InputError& error) {
    EXPECT_STREQ(error.what(), "boundary 'bottom' is not in the mesh (it has: 'contact' 'top')");
  }
}

TEST(TetMesh, BoundaryTrianglesAreTheUnsharedFacesOrientedOutward) {
  const stc::TetMesh mesh = twoTets();
  const auto faces = stc::boundaryTriangles(mesh);
  ASSERT_EQ(faces.size(), 6u);  // 8 faces, the shared one (0, 2, 3) is interior
  // Divergence theorem: V = (1/3) ∮ x · n dA = Σ_faces (1/6) x0 · ((x1 − x0) × (x2 − x0)).
  double volume = 0.0;
  for (const auto& f : faces) {
    const Eigen::Vector3d x0 = mesh.nodes.col(f[0]), x1 = mesh.nodes.col(f[1]), x2 = mesh.nodes.col(f[2]);
    volume += x0.dot((x1 - x0).cross(x2 - x0)) / 6.0;
  }
  EXPECT_NEAR(volume, 2.0 / 6.0, 1e-15);
}
