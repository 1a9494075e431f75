// The body and its mirror image (src/mesh/mirror_image.hpp): twice the nodes and elements, the
// image reflected across the plane gap/2 below the body, elements still positive, groups prefixed.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/half_ball.hpp"
#include "stcontact/mesh/half_disc.hpp"
#include "stcontact/mesh/mirror_image.hpp"

namespace {

TEST(MirrorImage, HalfDiscAndItsImageFaceEachOtherAcrossTheGap) {
  const stc::TriMesh body = stc::makeHalfDisc({1.0, 21, 1.135});
  const auto pair = std::get<stc::TriMesh>(stc::withMirrorImage(body, 0.02));
  const int n = body.numNodes();
  ASSERT_EQ(pair.numNodes(), 2 * n);
  ASSERT_EQ(pair.numElements(), 2 * body.numElements());
  for (int i = 0; i < n; ++i) {
    EXPECT_EQ(pair.nodes(0, n + i), body.nodes(0, i));
    EXPECT_NEAR(pair.nodes(1, n + i), -2.02 - body.nodes(1, i), 1e-15);  // plane y = −1.01
  }
  for (int e = 0; e < pair.numElements(); ++e) EXPECT_GT(pair.twiceSignedArea(e), 0.0) << e;
  EXPECT_EQ(pair.group("mirror_arc").nodes.size(), body.group("arc").nodes.size());
  EXPECT_EQ(pair.group("mirror_top").nodes.front(), body.group("top").nodes.front() + n);
  EXPECT_EQ(pair.group("arc").nodes, body.group("arc").nodes);
}

TEST(MirrorImage, HalfBallImageKeepsPositiveVolumesAndOutwardFaces) {
  const stc::TetMesh body = stc::makeHalfBall({1.0, 3, 1.5, 0.0});
  const auto pair = std::get<stc::TetMesh>(stc::withMirrorImage(body, 0.0));
  const int n = body.numNodes();
  for (int e = 0; e < pair.numElements(); ++e) EXPECT_GT(pair.sixSignedVolume(e), 0.0) << e;
  EXPECT_NEAR(pair.nodes.row(2).tail(n).maxCoeff(), body.nodes.row(2).minCoeff(), 1e-15);  // the poles touch
  // The image's group triangles stay outward: their normals point down where the body's point up.
  const auto& t = pair.group("mirror_top").triangles.front();
  const Eigen::Vector3d a = pair.nodes.col(t[1]) - pair.nodes.col(t[0]), b = pair.nodes.col(t[2]) - pair.nodes.col(t[0]);
  EXPECT_LT(a.cross(b).z(), 0.0);
}

TEST(MirrorImage, RefusesAMeshThatAlreadyHasAnImageGroupName) {
  stc::TriMesh body = stc::makeHalfDisc({1.0, 5, 1.135});
  body.groups["mirror_arc"] = body.groups.at("arc");
  EXPECT_THROW(stc::withMirrorImage(body, 0.1), stc::InputError);
}

}  // namespace
