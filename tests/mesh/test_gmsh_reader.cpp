// Tests of the MSH 4.1 reader: a hand-written two-triangle file read exactly, every kind of bad
// input refused with a message naming the file, and the shipped examples/meshes/punch.msh
// checked against its geometry (examples/meshes/punch.geo).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/missing_file_error.hpp"
#include "stcontact/mesh/body_mesh.hpp"
#include "stcontact/mesh/gmsh_reader.hpp"

namespace stc {
namespace {

// The unit square cut along its diagonal (nodes 1..4 counter-clockwise from the origin), with
// "bottom" on curve 1 (y = 0), "top" on curve 3 (y = 1), a point element and an unused node 9.
const std::string kSquare = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
3
1 1 "bottom"
1 2 "top"
2 3 "body"
$EndPhysicalNames
$Entities
5 4 1 0
1 0 0 0 0
2 1 0 0 0
3 1 1 0 0
4 0 1 0 0
5 5 5 0 0
1 0 0 0 1 0 0 1 1 2 1 -2
2 1 0 0 1 1 0 0 2 2 -3
3 0 1 0 1 1 0 1 2 2 3 -4
4 0 0 0 0 1 0 0 2 4 -1
1 0 0 0 1 1 0 1 3 4 1 2 3 4
$EndEntities
$Nodes
2 5 1 9
0 5 0 1
9
5 5 0
2 1 0 4
1
2
3
4
0 0 0
1 0 0
1 1 0
0 1 0
$EndNodes
$Elements
4 5 1 5
0 5 15 1
1 9
1 1 1 1
2 1 2
1 3 1 1
3 3 4
2 1 2 2
4 1 2 3
5 1 3 4
$EndElements
)";

TriMesh parse(const std::string& text) {
  std::istringstream in(text);
  return parseGmsh(in, "square.msh");
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

/// The message of the InputError that parsing `text` throws ("" if it throws none).
std::string errorOf(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GmshReader, ParsesTwoTriangleSquareExactly) {
  const TriMesh mesh = parse(kSquare);
  ASSERT_EQ(mesh.numNodes(), 4);  // node 9 is used by no triangle: dropped
  Eigen::Matrix<double, 2, 4> nodes;
  nodes << 0, 1, 1, 0,
           0, 0, 1, 1;
  EXPECT_EQ(mesh.nodes, nodes);
  ASSERT_EQ(mesh.numElements(), 2);
  Eigen::Matrix<int, 3, 2> triangles;
  triangles << 0, 0,
               1, 2,
               2, 3;
  EXPECT_EQ(mesh.triangles, triangles);
}

// The file's node tags are kept for the nodes used (what contact.csv and solution.h5 show), in the
// order of the mesh's nodes; a generated mesh has none and is numbered from 1.
TEST(GmshReader, KeepsTheFilesNodeTags) {
  std::string text = replaced(kSquare, "1\n2\n3\n4\n0 0 0", "40\n30\n20\n10\n0 0 0");
  text = replaced(text, "\n2 1 2\n", "\n2 40 30\n");
  text = replaced(text, "\n3 3 4\n", "\n3 20 10\n");
  text = replaced(text, "\n4 1 2 3\n", "\n4 40 30 20\n");
  text = replaced(text, "\n5 1 3 4\n", "\n5 40 20 10\n");
  const TriMesh mesh = parse(text);
  EXPECT_EQ(mesh.node_tags, (std::vector<long long>{40, 30, 20, 10}));
  EXPECT_EQ(nodeTags(BodyMesh(mesh)), (std::vector<long long>{40, 30, 20, 10}));
  TriMesh generated = mesh;
  generated.node_tags.clear();
  EXPECT_EQ(nodeTags(BodyMesh(generated)), (std::vector<long long>{1, 2, 3, 4}));
}

TEST(GmshReader, ReadsPhysicalGroupsByName) {
  const TriMesh mesh = parse(kSquare);
  ASSERT_EQ(mesh.groups.size(), 2u);  // "body" is a surface group, not a boundary
  EXPECT_EQ(mesh.group("bottom").edges, (std::vector<std::array<int, 2>>{{0, 1}}));
  EXPECT_EQ(mesh.group("bottom").nodes, (std::vector<int>{0, 1}));
  EXPECT_EQ(mesh.group("top").edges, (std::vector<std::array<int, 2>>{{2, 3}}));
  EXPECT_EQ(mesh.group("top").nodes, (std::vector<int>{2, 3}));
}

TEST(GmshReader, CurveInTwoGroupsFeedsBothAndUnnamedGroupIsNamedByNumber) {
  const TriMesh mesh = parse(replaced(kSquare, "1 0 0 0 1 0 0 1 1 2", "1 0 0 0 1 0 0 2 1 7 2"));
  EXPECT_EQ(mesh.group("bottom").edges, mesh.group("7").edges);
}

TEST(GmshReader, FlipsMeshWhoseTrianglesAreAllClockwise) {
  const TriMesh mesh = parse(replaced(replaced(kSquare, "\n4 1 2 3\n", "\n4 1 3 2\n"), "\n5 1 3 4\n",
                                  "\n5 1 4 3\n"));
  ASSERT_EQ(mesh.numElements(), 2);
  for (int e = 0; e < 2; ++e) EXPECT_DOUBLE_EQ(mesh.twiceSignedArea(e), 1.0);
}

TEST(GmshReader, ReportsInvertedElementOfMixedOrientationByName) {
  const std::string message = errorOf(replaced(kSquare, "\n5 1 3 4\n", "\n5 1 4 3\n"));
  EXPECT_EQ(message.rfind("square.msh: ", 0), 0u) << message;
  // Named by the file's element tag (5) and its line, not by its position among the triangles.
  EXPECT_NE(message.find(": triangle 5 is inverted"), std::string::npos) << message;
  EXPECT_NE(message.find(": line "), std::string::npos) << message;
}

TEST(GmshReader, ReportsFlatTriangleByTag) {
  // Node 3 moved onto the line through nodes 1 and 4 (x = 0): triangle 5 = (1, 3, 4) has no area.
  const std::string message = errorOf(replaced(kSquare, "\n1 1 0\n", "\n0 0.5 0\n"));
  EXPECT_NE(message.find("triangle 5 is degenerate"), std::string::npos) << message;
}

// Every cut at a line boundary (the complete text excepted) is refused as truncated, and so is
// every cut inside a line: a partial mesh is never returned.
TEST(GmshReader, RefusesFileTruncatedAtEveryLineBoundary) {
  int cuts = 0;
  for (std::size_t end = kSquare.find('\n'); end + 1 < kSquare.size();
       end = kSquare.find('\n', end + 1), ++cuts) {
    const std::string message = errorOf(kSquare.substr(0, end + 1));
    EXPECT_EQ(message.rfind("square.msh: ", 0), 0u) << "cut after byte " << end << ": " << message;
    EXPECT_TRUE(message.find("truncated") != std::string::npos ||
                message.find("empty file") != std::string::npos)
        << message;
  }
  EXPECT_EQ(errorOf(""), "square.msh: empty file (expected $MeshFormat)");
  EXPECT_EQ(cuts, 48);  // the text has 49 lines
}

TEST(GmshReader, RefusesFileTruncatedInsideAnyLine) {
  // Cutting only the final newline leaves a complete file; every shorter prefix is refused.
  for (std::size_t length = 1; length + 1 < kSquare.size(); ++length)
    EXPECT_EQ(errorOf(kSquare.substr(0, length)).rfind("square.msh: ", 0), 0u) << length;
  EXPECT_NO_THROW(parse(kSquare.substr(0, kSquare.size() - 1)));
}

TEST(GmshReader, RefusesOtherVersionsAndBinaryNamingTheVersion) {
  const std::string old = errorOf(replaced(kSquare, "4.1 0 8", "2.2 0 8"));
  EXPECT_EQ(old.rfind("square.msh: unsupported mesh format: version 2.2 ASCII", 0), 0u) << old;
  const std::string binary = errorOf(replaced(kSquare, "4.1 0 8", "4.1 1 8"));
  EXPECT_EQ(binary.rfind("square.msh: unsupported mesh format: version 4.1 binary", 0), 0u)
      << binary;
}

TEST(GmshReader, RefusesNodeOutsidePlaneAsNot2D) {
  const std::string message = errorOf(replaced(kSquare, "1 1 0\n0 1 0", "1 1 0.5\n0 1 0"));
  EXPECT_EQ(message, "square.msh: line 35: not a 2D mesh: node 3 has z = 0.5 (all nodes must lie "
                     "in the plane z = 0; a volume mesh needs dimension = 3 in the scene)");
}

TEST(GmshReader, NamesLineAndNodeOfShortCoordinateLine) {
  const std::string message = errorOf(replaced(kSquare, "1 0 0\n1 1 0", "1 0\n1 1 0"));
  EXPECT_EQ(message, "square.msh: line 34: expected 3 numbers (x y z) for node 2, found 2");
}

TEST(GmshReader, RefusesUnsupportedElementTypeNamingIt) {
  const std::string message =
      errorOf(replaced(kSquare, "2 1 2 2\n4 1 2 3\n5 1 3 4", "2 1 3 1\n4 1 2 3 4"));
  EXPECT_NE(message.find("element type 3 (4-node quadrangle) is not supported"), std::string::npos)
      << message;
}

TEST(GmshReader, RefusesARepeatedTriangleNamingBoth) {
  EXPECT_EQ(errorOf(replaced(kSquare, "\n5 1 3 4\n", "\n5 1 2 3\n")),
            "square.msh: line 48: triangle 5 repeats triangle 4 (the same three nodes)");
}

TEST(GmshReader, RefusesOverlappingTrianglesNamingTheirEdge) {
  // Triangle 5 = (1, 2, 4) lies above the edge 1 → 2, as triangle 4 = (1, 2, 3) does.
  EXPECT_EQ(errorOf(replaced(kSquare, "\n5 1 3 4\n", "\n5 1 2 4\n")),
            "square.msh: line 48: triangle 5 overlaps triangle 4 (both lie on the same side of their edge from "
            "node 1 to node 2)");
}

TEST(GmshReader, RefusesABoundaryElementInsideTheBody) {
  // The diagonal 1–3, which triangles 4 and 5 share, given to "top" (3D refuses the same case).
  EXPECT_EQ(errorOf(replaced(kSquare, "\n3 3 4\n", "\n3 1 3\n")),
            "square.msh: line 45: element 3 of boundary 'top' lies inside the body (two triangles share it): a "
            "boundary group holds edges of the body's boundary only");
}

TEST(GmshReader, RefusesAnEdgeRepeatedInAGroup) {
  const std::string twice = replaced(replaced(kSquare, "4 5 1 5\n", "4 6 1 6\n"), "1 1 1 1\n2 1 2\n",
                                     "1 1 1 2\n2 1 2\n6 2 1\n");
  EXPECT_EQ(errorOf(twice), "square.msh: line 44: element 6 of boundary 'bottom' repeats an edge already in it");
}

TEST(GmshReader, RefusesBoundaryEdgeOnNodeNoTriangleUses) {
  const std::string message = errorOf(replaced(kSquare, "\n3 3 4\n", "\n3 3 9\n"));
  EXPECT_NE(message.find("uses node 9, which no triangle uses"), std::string::npos) << message;
}

TEST(GmshReader, RefusesElementOnUnknownNode) {
  const std::string message = errorOf(replaced(kSquare, "\n5 1 3 4\n", "\n5 1 3 8\n"));
  EXPECT_NE(message.find("element 5 uses node 8, which $Nodes does not list"), std::string::npos)
      << message;
}

TEST(GmshReader, RefusesMissingFileNamingIt) {
  try {
    readGmsh("/nonexistent/part.msh");
    FAIL() << "no MissingFileError";
  } catch (const MissingFileError& e) {  // an InputError that also carries the path (Python: FileNotFoundError)
    EXPECT_EQ(std::string(e.what()), "cannot open mesh file '/nonexistent/part.msh'");
    EXPECT_EQ(e.path(), "/nonexistent/part.msh");
  }
}

TEST(GmshReader, AFolderIsAnInputErrorButNotAMissingFile) {
  const std::string folder = std::filesystem::temp_directory_path().string();
  try {
    readGmsh(folder);
    FAIL() << "no InputError";
  } catch (const MissingFileError&) {
    FAIL() << "a folder exists: not a missing file";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot open mesh file '" + folder + "'");
  }
}

// ---- The shipped punch: 2 x 1 block, bottom corners rounded with r = 0.25 (punch.geo). ----

constexpr double kRadius = 0.25;

TriMesh readPunch() { return readGmsh(std::string(STC_SOURCE_DIR) + "/examples/meshes/punch.msh"); }

/// Centre of the corner arc that the point p lies on, if it is on one.
std::optional<Eigen::Vector2d> arcCentre(const Eigen::Vector2d& p) {
  for (double side : {-1.0, 1.0}) {
    const Eigen::Vector2d centre(side * (1 - kRadius), kRadius);
    if (std::abs((p - centre).norm() - kRadius) < 1e-9 && side * p.x() >= 1 - kRadius - 1e-12 &&
        p.y() <= kRadius + 1e-12)
      return centre;
  }
  return std::nullopt;
}

TEST(GmshReader, PunchHasModerateSizeAndLiesOnOrAboveYZero) {
  const TriMesh mesh = readPunch();
  EXPECT_GE(mesh.numNodes(), 300);
  EXPECT_LE(mesh.numNodes(), 800);
  EXPECT_DOUBLE_EQ(mesh.nodes.row(1).minCoeff(), 0.0);  // the scene's obstacle is just below
  EXPECT_DOUBLE_EQ(mesh.nodes.row(0).minCoeff(), -1.0);
  EXPECT_DOUBLE_EQ(mesh.nodes.row(0).maxCoeff(), 1.0);
  EXPECT_DOUBLE_EQ(mesh.nodes.row(1).maxCoeff(), 1.0);
}

// Exact area A = 2 - 2 r^2 (1 - pi/4). The mesh is the polygon through boundary nodes that lie on
// the exact boundary, so it misses exactly the circular segments cut off by the chords on the
// arcs, each r^2/2 (theta - sin theta): A_mesh + sum(segments) = A up to rounding. A cruder bound
// (sagitta c^2/(8r) times chord c, summed) checks that the gap is small as well as accounted for.
TEST(GmshReader, PunchAreaIsGeometricAreaLessArcSegments) {
  const TriMesh mesh = readPunch();
  double area = 0.0;
  for (int e = 0; e < mesh.numElements(); ++e) {
    ASSERT_GT(mesh.twiceSignedArea(e), 0.0) << e;
    area += 0.5 * mesh.twiceSignedArea(e);
  }
  double segments = 0.0, bound = 0.0;
  int arc_edges = 0;
  for (const auto& [a, b] : mesh.group("bottom").edges) {
    const Eigen::Vector2d p = mesh.nodes.col(a), q = mesh.nodes.col(b);
    const auto ca = arcCentre(p), cb = arcCentre(q);
    if (!ca || !cb || *ca != *cb) continue;
    const double chord = (q - p).norm();
    const double theta = 2 * std::asin(chord / (2 * kRadius));
    segments += 0.5 * kRadius * kRadius * (theta - std::sin(theta));
    bound += chord * chord * chord / (8 * kRadius);
    ++arc_edges;
  }
  const double exact = 2 - 2 * kRadius * kRadius * (1 - std::numbers::pi / 4);
  EXPECT_GE(arc_edges, 10);
  EXPECT_NEAR(area + segments, exact, 1e-12);
  EXPECT_GT(exact - area, 0.0);
  EXPECT_LE(exact - area, bound);
}

TEST(GmshReader, PunchTopGroupCoversTopEdge) {
  const TriMesh mesh = readPunch();
  const BoundaryGroup& top = mesh.group("top");
  ASSERT_FALSE(top.nodes.empty());
  for (int n : top.nodes) EXPECT_DOUBLE_EQ(mesh.nodes(1, n), 1.0) << n;
  double length = 0.0;
  for (const auto& [a, b] : top.edges) length += (mesh.nodes.col(b) - mesh.nodes.col(a)).norm();
  EXPECT_NEAR(length, 2.0, 1e-12);
}

TEST(GmshReader, PunchBottomGroupLiesOnFlatAndArcsAndSpansThem) {
  const TriMesh mesh = readPunch();
  const BoundaryGroup& bottom = mesh.group("bottom");
  ASSERT_FALSE(bottom.nodes.empty());
  double xmin = 0.0, xmax = 0.0;
  for (int n : bottom.nodes) {
    const Eigen::Vector2d p = mesh.nodes.col(n);
    const bool flat = p.y() == 0.0 && std::abs(p.x()) <= 1 - kRadius;
    EXPECT_TRUE(flat || arcCentre(p)) << "node " << n << " at " << p.transpose();
    xmin = std::min(xmin, p.x());
    xmax = std::max(xmax, p.x());
  }
  EXPECT_DOUBLE_EQ(xmin, -1.0);  // the arcs end at (+-1, r)
  EXPECT_DOUBLE_EQ(xmax, 1.0);
  // Every node at the lowest level y = 0 is a potential contact node.
  for (int n = 0; n < mesh.numNodes(); ++n)
    if (mesh.nodes(1, n) == 0.0)
      EXPECT_TRUE(std::binary_search(bottom.nodes.begin(), bottom.nodes.end(), n)) << n;
}

}  // namespace
}  // namespace stc
