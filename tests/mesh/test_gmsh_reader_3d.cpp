// Tests of the MSH 4.1 reader for volume meshes: tests/mesh/data/cube.msh (the unit cube as six
// tetrahedra around its diagonal from the origin, "bottom" on z = 0 and "top" on z = 1) read
// exactly, tetrahedra oriented, surface triangles outward, and bad input refused naming file and line.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <fstream>
#include <sstream>
#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/gmsh_reader.hpp"

namespace stc {
namespace {

const std::string kCubeFile = std::string(STC_SOURCE_DIR) + "/tests/mesh/data/cube.msh";

std::string cubeText() {
  std::ifstream in(kCubeFile);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "no '" << from << "'";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

template <class Parse>
std::string errorOf(const std::string& text, Parse parse) {
  std::istringstream in(text);
  try {
    parse(in, "cube.msh");
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

std::string error3d(const std::string& text) {
  return errorOf(text, [](std::istream& in, const std::string& name) { parseGmsh3d(in, name); });
}

Eigen::Vector3d normalOf(const TetMesh& mesh, const std::array<int, 3>& t) {
  const Eigen::Vector3d a = mesh.nodes.col(t[1]) - mesh.nodes.col(t[0]), b = mesh.nodes.col(t[2]) - mesh.nodes.col(t[0]);
  return a.cross(b).normalized();
}

}  // namespace

TEST(GmshReader3d, ReadsTheCubeWithPositiveTetrahedraAndOutwardBoundaries) {
  const TetMesh mesh = readGmsh3d(kCubeFile);
  EXPECT_EQ(mesh.numNodes(), 8);
  EXPECT_EQ(mesh.numElements(), 6);
  double volume = 0.0;
  for (int e = 0; e < mesh.numElements(); ++e) {
    EXPECT_GT(mesh.sixSignedVolume(e), 0.0) << "element " << e;
    volume += mesh.sixSignedVolume(e) / 6.0;
  }
  EXPECT_NEAR(volume, 1.0, 1e-15);
  for (const auto& [name, z] : {std::pair<std::string, double>{"bottom", -1.0}, {"top", 1.0}}) {
    const SurfaceGroup& group = mesh.group(name);
    EXPECT_EQ(group.triangles.size(), 2u) << name;
    EXPECT_EQ(group.nodes.size(), 4u) << name;
    for (const auto& t : group.triangles) EXPECT_EQ(normalOf(mesh, t), Eigen::Vector3d(0, 0, z)) << name;
  }
}

TEST(GmshReader3d, RefusesADegenerateTetrahedronNamingItsTagAndLine) {
  // Element 5 made flat: four nodes of the face z = 0.
  EXPECT_EQ(error3d(replaced(cubeText(), "\n5 1 2 4 8\n", "\n5 1 2 4 3\n")),
            "cube.msh: line 45: tetrahedron 5 is degenerate (zero volume)");
}

TEST(GmshReader3d, RefusesABoundaryTriangleThatIsNotABoundaryFace) {
  // (1, 4, 8) is the face elements 5 and 7 share, inside the cube.
  EXPECT_EQ(error3d(replaced(cubeText(), "\n1 1 2 4\n", "\n1 1 4 8\n")),
            "cube.msh: line 39: triangle 1 of boundary 'bottom' is not a boundary face of the tetrahedra");
}

TEST(GmshReader3d, RefusesARepeatedTetrahedronNamingBoth) {
  EXPECT_EQ(error3d(replaced(cubeText(), "\n6 1 2 6 8\n", "\n6 1 2 4 8\n")),
            "cube.msh: line 46: tetrahedron 6 repeats tetrahedron 5 (the same four nodes)");
}

TEST(GmshReader3d, RefusesOverlappingTetrahedra) {
  // Tetrahedron 6 = (1, 2, 4, 6) lies above the face (1, 2, 4) on z = 0, as tetrahedron 5 does.
  EXPECT_EQ(error3d(replaced(cubeText(), "\n6 1 2 6 8\n", "\n6 1 2 4 6\n")),
            "cube.msh: line 46: tetrahedron 6 overlaps tetrahedron 5 (both lie on the same side of a face they share)");
}

TEST(GmshReader3d, RefusesAFaceRepeatedInAGroup) {
  EXPECT_EQ(error3d(replaced(cubeText(), "\n2 1 3 4\n", "\n2 1 2 4\n")),
            "cube.msh: line 40: triangle 2 of boundary 'bottom' repeats a face already in it");
}

TEST(GmshReader3d, RefusesOtherElementTypesNamingThem) {
  const std::string message = error3d(replaced(cubeText(), "3 1 4 6\n5 1 2 4 8", "3 1 5 6\n5 1 2 4 8"));
  EXPECT_NE(message.find("element type 5 (8-node hexahedron) is not supported: the reader takes 4-node tetrahedra"),
            std::string::npos)
      << message;
}

TEST(GmshReader3d, TheTwoDimensionalReaderSaysToSetTheDimension) {
  const std::string message =
      errorOf(cubeText(), [](std::istream& in, const std::string& name) { parseGmsh(in, name); });
  EXPECT_NE(message.find("needs dimension = 3 in the scene"), std::string::npos) << message;
}

TEST(GmshReader3d, RefusesATruncatedFile) {
  const std::string text = cubeText();
  EXPECT_EQ(error3d(text.substr(0, text.find("$EndNodes"))), "cube.msh: truncated file (expected $EndNodes)");
}

}  // namespace stc
