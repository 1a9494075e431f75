// The extruded half-disc: sizes, exact volume, groups on their surfaces, a closed outward surface.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/half_disc_slab.hpp"

namespace {

stc::HalfDiscSlabOptions options(double thickness, int layers) {
  stc::HalfDiscSlabOptions o;
  o.section = {1.5, 21, 1.135};
  o.thickness = thickness;
  o.layers = layers;
  return o;
}

double sectionArea(const stc::TriMesh& m) {
  double area = 0.0;
  for (int e = 0; e < m.numElements(); ++e) {
    const Eigen::Vector2d a = m.nodes.col(m.triangles(0, e)), b = m.nodes.col(m.triangles(1, e)),
                          c = m.nodes.col(m.triangles(2, e));
    area += 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  }
  return area;
}

}  // namespace

TEST(HalfDiscSlab, SizesAndVolumeAreTheSectionsTimesTheLayers) {
  const auto o = options(0.2, 3);
  const stc::TriMesh section = stc::makeHalfDisc(o.section);
  const stc::TetMesh slab = stc::makeHalfDiscSlab(o);
  EXPECT_EQ(slab.numNodes(), 4 * section.numNodes());
  EXPECT_EQ(slab.numElements(), 3 * 3 * section.numElements());
  double volume = 0.0;
  for (int e = 0; e < slab.numElements(); ++e) {
    EXPECT_GT(slab.sixSignedVolume(e), 0.0);
    volume += slab.sixSignedVolume(e) / 6.0;
  }
  EXPECT_NEAR(volume, 0.2 * sectionArea(section), 1e-14);
}

// Every boundary triangle is named (a non-conforming split would leave unnamed inner faces, and
// the surface would not close): the divergence theorem over all groups gives the volume.
TEST(HalfDiscSlab, GroupsLieOnTheirSurfacesAndCloseTheBody) {
  const stc::TetMesh slab = stc::makeHalfDiscSlab(options(0.1, 2));
  for (int n : slab.group("front").nodes) EXPECT_EQ(slab.nodes(2, n), 0.0);
  for (int n : slab.group("back").nodes) EXPECT_EQ(slab.nodes(2, n), 0.1);
  for (int n : slab.group("top").nodes) EXPECT_EQ(slab.nodes(1, n), 0.0);
  for (int n : slab.group("arc").nodes) EXPECT_NEAR(slab.nodes.col(n).head<2>().norm(), 1.5, 1e-12);
  double volume = 0.0, surface = 0.0;
  for (int e = 0; e < slab.numElements(); ++e) volume += slab.sixSignedVolume(e) / 6.0;
  for (const char* name : {"front", "back", "top", "arc"})
    for (const auto& f : slab.group(name).triangles) {
      const Eigen::Vector3d x0 = slab.nodes.col(f[0]), x1 = slab.nodes.col(f[1]), x2 = slab.nodes.col(f[2]);
      surface += x0.dot((x1 - x0).cross(x2 - x0)) / 6.0;
    }
  EXPECT_NEAR(surface, volume, 1e-14);
}

TEST(HalfDiscSlab, OptionsAreChecked) {
  EXPECT_THROW(stc::makeHalfDiscSlab(options(0.0, 2)), stc::InputError);
  EXPECT_THROW(stc::makeHalfDiscSlab(options(0.1, 0)), stc::InputError);
}
