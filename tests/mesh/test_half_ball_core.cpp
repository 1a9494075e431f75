// Half-ball generator with a uniformly meshed core (HalfBallOptions::core): valid and conforming
// for every size that fits, the requested cell size at the pole, geometric growth outside, checks.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/half_ball.hpp"

namespace {

stc::TetMesh cored(int divisions, double core, double radius = 1.0) {
  return stc::makeHalfBall({radius, divisions, 1.5, core});
}

int poleNode(int divisions) { return divisions + (2 * divisions + 1) * divisions; }

// The lengths of the edges of the elements that touch node n.
std::vector<double> edgeLengthsAround(const stc::TetMesh& mesh, int n) {
  std::vector<double> lengths;
  for (int e = 0; e < mesh.numElements(); ++e) {
    if (!(mesh.tets.col(e).array() == n).any()) continue;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        lengths.push_back((mesh.nodes.col(mesh.tets(a, e)) - mesh.nodes.col(mesh.tets(b, e))).norm());
  }
  return lengths;
}

}  // namespace

// A non-conforming junction between core, shells and outer grid would leave faces that belong to one
// element only inside the body: every such face must lie on the sphere or on the top plane. The
// generator itself validates the volumes (positive, none degenerate).
TEST(HalfBallCore, EveryMeshThatFitsIsValidAndConforming) {
  const double radius = 1.4;
  for (int divisions : {2, 3, 4, 6})
    for (double core : {0.05, 0.1, 0.2, 0.3}) {
      if (core >= double(divisions) / (2 * divisions + 1)) continue;
      const stc::TetMesh mesh = cored(divisions, core, radius);
      for (int node : mesh.group("contact").nodes) EXPECT_NEAR(mesh.nodes.col(node).norm(), radius, 1e-12);
      for (int node : mesh.group("top").nodes) EXPECT_EQ(mesh.nodes(2, node), 0.0);
      double volume = 0.0, surface_volume = 0.0;
      for (int e = 0; e < mesh.numElements(); ++e) volume += mesh.sixSignedVolume(e) / 6.0;
      for (const char* name : {"top", "contact"})
        for (const auto& f : mesh.group(name).triangles) {
          const Eigen::Vector3d x0 = mesh.nodes.col(f[0]), x1 = mesh.nodes.col(f[1]), x2 = mesh.nodes.col(f[2]);
          surface_volume += x0.dot((x1 - x0).cross(x2 - x0)) / 6.0;
        }
      EXPECT_NEAR(surface_volume, volume, 1e-12) << "closed and outward (divergence theorem)";
      const double exact = 2.0 / 3.0 * std::numbers::pi * radius * radius * radius;
      EXPECT_GT(volume, 0.97 * exact) << "divisions " << divisions << ", core " << core;
      EXPECT_LT(volume, exact);
    }
}

// At the pole the elements have the core's size h = s0 R / d: the map onto the ball shrinks the core
// by at most 1 − cos(atan(√2 s0)) ≈ s0² (2 % at s0 = 0.1), and the diagonals are √2 and √3 h.
TEST(HalfBallCore, PoleElementsHaveTheCoreCellSize) {
  for (int divisions : {3, 6}) {
    const double radius = 2.0, core = 0.1, h = core * radius / divisions;
    const stc::TetMesh mesh = cored(divisions, core, radius);
    const int pole = poleNode(divisions);
    EXPECT_NEAR((mesh.nodes.col(pole) - Eigen::Vector3d(0.0, 0.0, -radius)).norm(), 0.0, 1e-14);
    const std::vector<double> lengths = edgeLengthsAround(mesh, pole);
    EXPECT_NEAR(*std::min_element(lengths.begin(), lengths.end()), h, 0.02 * h);
    EXPECT_LE(*std::max_element(lengths.begin(), lengths.end()), std::sqrt(3.0) * h * 1.0001);
  }
}

// Refining the core (smaller s0 at the same d) adds shells, ln(s1/s0) / ln(1 + 1/d) of them, each a
// copy of the core's surface: from s0 = 0.1 to 0.05 the node count grows by about ln 2 / ln(1 + 1/d)
// surface copies (d = 4: 3.1 layers of 9² + 4·2·4² = 209 nodes; the layer count is rounded up, hence
// ±1), i.e. the cost of refining the contact zone is logarithmic in the size ratio, not cubic.
TEST(HalfBallCore, HalvingTheCoreAddsAFewShells) {
  const int d = 4;
  const stc::TetMesh a = cored(d, 0.1), b = cored(d, 0.05);
  const int surface = (2 * d + 1) * (2 * d + 1) + 4 * 2 * d * d;  // nodes on ‖x − P‖_∞ = s0 (top + 4 sides)
  const double layers = double(b.numNodes() - a.numNodes()) / surface;
  std::printf("core 0.1: %d nodes, core 0.05: %d nodes, %.2f more layers (ln 2 / ln 1.25 = %.2f)\n", a.numNodes(),
              b.numNodes(), layers, std::log(2.0) / std::log1p(1.0 / d));
  EXPECT_NEAR(layers, std::log(2.0) / std::log1p(1.0 / d), 1.0);
}

TEST(HalfBallCore, CoreMustFitInsideTheOuterGridsHole) {
  EXPECT_THROW(cored(4, 0.0 - 0.1), stc::InputError);
  EXPECT_THROW(cored(4, 1.0), stc::InputError);
  try {
    cored(4, 0.45);  // 4 / 9 = 0.444
    FAIL() << "core above divisions / (2 divisions + 1) accepted";
  } catch (const stc::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("divisions / (2 divisions + 1)"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(cored(4, 0.44));
}
