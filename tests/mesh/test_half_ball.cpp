// Half-ball generator: sizes, volume under refinement, groups on their surfaces, grading.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/half_ball.hpp"

namespace {

using std::numbers::pi;

double totalVolume(const stc::TetMesh& mesh) {
  double volume = 0.0;
  for (int e = 0; e < mesh.numElements(); ++e) volume += mesh.sixSignedVolume(e) / 6.0;
  return volume;
}

int poleNode(int divisions) { return divisions + (2 * divisions + 1) * divisions; }

// Mean volume of the elements that touch node n.
double meanVolumeAround(const stc::TetMesh& mesh, int n) {
  double sum = 0.0;
  int count = 0;
  for (int e = 0; e < mesh.numElements(); ++e)
    if ((mesh.tets.col(e).array() == n).any()) {
      sum += mesh.sixSignedVolume(e) / 6.0;
      ++count;
    }
  return sum / count;
}

}  // namespace

TEST(HalfBall, DefaultSizes) {
  const stc::TetMesh mesh = stc::makeHalfBall({});
  EXPECT_EQ(mesh.numNodes(), 2601);
  EXPECT_EQ(mesh.numDofs(), 7803);
  EXPECT_EQ(mesh.numElements(), 12288);
}

TEST(HalfBall, EveryTetrahedronHasPositiveVolume) {
  for (double grading : {1.0, 1.5, 2.0})
    for (int divisions : {2, 3, 5, 8, 12}) {
      const stc::TetMesh mesh = stc::makeHalfBall({1.0, divisions, grading});
      double smallest = INFINITY;
      for (int e = 0; e < mesh.numElements(); ++e) smallest = std::min(smallest, mesh.sixSignedVolume(e));
      EXPECT_GT(smallest, 0.0) << "divisions " << divisions << ", grading " << grading;
    }
}

TEST(HalfBall, VolumeTendsToTheHalfBallsAtSecondOrder) {
  // The boundary nodes lie on the sphere, so the mesh is a polyhedron inscribed in the half-ball:
  // its volume is smaller, and each surface triangle of diameter h ~ R/d cuts off a cap of depth
  // at most h²/(8R), so the relative deficit is O(d⁻²). Measured: 0.29/d² (grading 1 and 1.5) and
  // 0.32/d² (grading 2) for d = 4..16; the bound 0.4/d² leaves room for round-off and nothing else.
  const double radius = 1.7, exact = 2.0 / 3.0 * pi * radius * radius * radius;
  for (double grading : {1.0, 1.5, 2.0}) {
    double previous = 0.0;
    for (int divisions : {4, 8, 16}) {
      const double deficit = (exact - totalVolume(stc::makeHalfBall({radius, divisions, grading}))) / exact;
      std::printf("grading %.1f, divisions %2d: relative volume deficit %.3e (× d² = %.3f)\n", grading, divisions,
                  deficit, deficit * divisions * divisions);
      EXPECT_GT(deficit, 0.0);
      EXPECT_LT(deficit, 0.4 / (divisions * divisions));
      if (previous > 0.0) EXPECT_GT(previous / deficit, 3.5) << "second order: halving h divides it by ~4";
      previous = deficit;
    }
  }
}

TEST(HalfBall, GroupsLieOnTheirSurfaces) {
  const double radius = 2.5;
  const stc::TetMesh mesh = stc::makeHalfBall({radius, 6, 1.5});
  ASSERT_FALSE(mesh.group("top").triangles.empty());
  ASSERT_FALSE(mesh.group("contact").triangles.empty());
  EXPECT_EQ(mesh.groups.size(), 2u);
  for (int node : mesh.group("top").nodes) EXPECT_EQ(mesh.nodes(2, node), 0.0);
  for (int node : mesh.group("contact").nodes) {
    EXPECT_NEAR(mesh.nodes.col(node).norm(), radius, 1e-12 * radius);
    EXPECT_LE(mesh.nodes(2, node), 0.0);
  }
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int a = 0; a < 4; ++a) {
      const Eigen::Vector3d x = mesh.nodes.col(mesh.tets(a, e));
      EXPECT_LE(x.norm(), radius * (1.0 + 1e-12));
      EXPECT_LE(x.z(), 0.0);
    }
  const int pole = poleNode(6);
  EXPECT_TRUE(std::binary_search(mesh.group("contact").nodes.begin(), mesh.group("contact").nodes.end(), pole));
  EXPECT_NEAR((mesh.nodes.col(pole) - Eigen::Vector3d(0.0, 0.0, -radius)).norm(), 0.0, 1e-15);
}

TEST(HalfBall, SurfaceIsClosedAndOrientedOutward) {
  // Divergence theorem over the two groups together: (1/3) ∮ x · n dA equals the mesh volume
  // only if the surface triangles close the body and all point outward.
  const stc::TetMesh mesh = stc::makeHalfBall({1.3, 5, 2.0});
  double volume = 0.0;
  for (const char* name : {"top", "contact"})
    for (const auto& f : mesh.group(name).triangles) {
      const Eigen::Vector3d x0 = mesh.nodes.col(f[0]), x1 = mesh.nodes.col(f[1]), x2 = mesh.nodes.col(f[2]);
      volume += x0.dot((x1 - x0).cross(x2 - x0)) / 6.0;
    }
  EXPECT_NEAR(volume, totalVolume(mesh), 1e-13);
}

TEST(HalfBall, GradingShrinksTheElementsAtThePole) {
  // Map 1 scales lengths near the pole by s^{p−1} with s ~ 1/d, so the elements touching it have
  // volumes ~ d^{−3p}: from d = 8 to 16 they shrink by 2^{3p} (measured below), and at fixed d a
  // larger p gives smaller ones.
  const int d = 8;
  double previous = INFINITY;
  for (double grading : {1.0, 1.5, 2.0}) {
    const stc::TetMesh coarse = stc::makeHalfBall({1.0, d, grading});
    const stc::TetMesh fine = stc::makeHalfBall({1.0, 2 * d, grading});
    const double atPole = meanVolumeAround(coarse, poleNode(d));
    const double mean = totalVolume(coarse) / coarse.numElements();
    const double shrink = atPole / meanVolumeAround(fine, poleNode(2 * d));
    std::printf("grading %.1f: pole elements / mean element = %.3e; pole elements d = 8 / d = 16 = %.2f\n", grading,
                atPole / mean, shrink);
    EXPECT_LT(atPole / mean, previous);
    EXPECT_NEAR(std::log2(shrink) / 3.0, grading, 0.02);
    previous = atPole / mean;
  }
}

TEST(HalfBall, OptionsAreChecked) {
  EXPECT_THROW(stc::makeHalfBall({0.0, 8, 1.5}), stc::InputError);
  EXPECT_THROW(stc::makeHalfBall({1.0, 1, 1.5}), stc::InputError);
  EXPECT_THROW(stc::makeHalfBall({1.0, 8, 0.9}), stc::InputError);
  EXPECT_THROW(stc::makeHalfBall({1.0, 8, 2.5}), stc::InputError);
}

TEST(HalfBall, NodeCountIsTheGeneratorsForTheGradedGrid) {
  for (int divisions : {2, 3, 5, 8})
    EXPECT_EQ(stc::halfBallNodeCount({1.0, divisions, 1.5, 0.0}), stc::makeHalfBall({1.0, divisions, 1.5, 0.0}).numNodes());
  // With a core: an upper bound (the outer grid, the core and its shells).
  const stc::HalfBallOptions cored{1.0, 4, 1.5, 0.2};
  EXPECT_GE(stc::halfBallNodeCount(cored), stc::makeHalfBall(cored).numNodes());
  EXPECT_THROW(stc::makeHalfBall({1.0, 2000, 1.5, 0.0}), stc::InputError);  // 3.2e10 nodes
}
