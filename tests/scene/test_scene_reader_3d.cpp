// Scene reader, 3D scenes: `dimension = 3` with the half_ball generator, three-entry vectors and
// component z; and the rules that keep 2D and 3D keys apart, each an InputError naming the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace stc {
namespace {

using ::testing::HasSubstr;

const std::filesystem::path kHemisphere = std::filesystem::path(STC_SOURCE_DIR) / "examples/scenes/hemisphere.toml";

std::string errorOf(const std::vector<std::string>& overrides) {
  try {
    readScene(kHemisphere, overrides);
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

}  // namespace

TEST(SceneReader3d, HemisphereReadsEveryThreeDimensionalValue) {
  const Scene s = readScene(kHemisphere);
  EXPECT_EQ(s.dimension, 3);
  EXPECT_EQ(s.mesh.generator, "half_ball");
  EXPECT_EQ(s.mesh.divisions, 8);
  EXPECT_EQ(s.mesh.grading, 1.5);
  EXPECT_EQ(s.mesh.core, 0.0);
  EXPECT_EQ(s.obstacle.point, Eigen::Vector3d(0.0, 0.0, -1.01));
  EXPECT_EQ(s.obstacle.normal, Eigen::Vector3d(0.0, 0.0, 1.0));
  ASSERT_EQ(s.dirichlet.size(), 3u);
  EXPECT_EQ(s.dirichlet[2].component, Component::Z);
}

TEST(SceneReader3d, CoreOfTheHalfBall) {
  EXPECT_EQ(readScene(kHemisphere, {"mesh.core=0.07"}).mesh.core, 0.07);
}

TEST(SceneReader3d, SlabReadsItsGeneratorKeys) {
  const auto slab = std::filesystem::path(STC_SOURCE_DIR) / "examples/scenes/slab.toml";
  const Scene s = readScene(slab);
  EXPECT_EQ(s.mesh.generator, "half_disc_slab");
  EXPECT_EQ(s.mesh.arc_nodes, 101);
  EXPECT_EQ(s.mesh.thickness, 0.05);
  EXPECT_EQ(s.mesh.layers, 2);
  const auto errorIn = [&](const std::string& override) {
    try {
      readScene(slab, {override});
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no InputError");
  };
  EXPECT_THAT(errorIn("mesh.thickness=0"), HasSubstr("key 'mesh.thickness' = 0 is out of range: must be > 0"));
  EXPECT_THAT(errorIn("mesh.layers=0"), HasSubstr("key 'mesh.layers' = 0 is out of range: must be >= 1"));
  EXPECT_THAT(errorIn("mesh.divisions=4"), HasSubstr("key 'mesh.divisions' applies to generator = \"half_ball\""));
  EXPECT_THAT(errorOf({"mesh.layers=2"}),
              HasSubstr("key 'mesh.layers' applies to generator = \"half_disc_slab\""));
  EXPECT_THAT(errorOf({"mesh.arc_nodes=31"}),
              HasSubstr("applies to generator = \"half_disc\" or \"half_disc_slab\""));
}

TEST(SceneReader3d, DimensionIsTwoOrThree) {
  EXPECT_THAT(errorOf({"dimension=4"}), HasSubstr("key 'dimension' = 4 is out of range: must be 2 or 3"));
}

TEST(SceneReader3d, GeneratorAndItsKeysFollowTheDimension) {
  EXPECT_THAT(errorOf({"mesh.generator=half_disc"}), HasSubstr("key 'mesh.generator' = \"half_disc\" is not one of \"half_ball\""));
  EXPECT_THAT(errorOf({"mesh.arc_nodes=31"}), HasSubstr("key 'mesh.arc_nodes' applies to generator = \"half_disc\""));
  EXPECT_THAT(errorOf({"mesh.grading=2.5"}), HasSubstr("key 'mesh.grading' = 2.5 is out of range: must be in [1, 2]"));
  EXPECT_THAT(errorOf({"mesh.divisions=1"}), HasSubstr("key 'mesh.divisions' = 1 is out of range: must be >= 2"));
  EXPECT_THAT(errorOf({"mesh.core=1.5"}),
              HasSubstr("key 'mesh.core' = 1.5 is out of range: must be 0 (no core) or in (0, 1)"));
  try {
    readScene(std::filesystem::path(STC_SOURCE_DIR) / "examples/scenes/hemicylinder.toml", {"mesh.core=0.1"});
    ADD_FAILURE() << "mesh.core accepted in a 2D scene";
  } catch (const InputError& error) {
    EXPECT_THAT(std::string(error.what()), HasSubstr("key 'mesh.core' applies to generator = \"half_ball\""));
  }
  EXPECT_THAT(errorOf({"model.plane=strain"}), HasSubstr("applies to 2D scenes only"));
}

TEST(SceneReader3d, VectorsHaveThreeEntries) {
  EXPECT_THAT(errorOf({"obstacle.point=[0.0, -1.01]"}),
              HasSubstr("key 'obstacle.point' must have 3 entries [x, y, z], got 2"));
}

TEST(SceneReader3d, ComponentZOnlyInThreeDimensions) {
  EXPECT_NO_THROW(readScene(kHemisphere));
  EXPECT_THAT(errorOf({"dimension=2", "mesh.generator=half_disc", "mesh.divisions=8"}),
              HasSubstr("key 'mesh.divisions' applies to generator = \"half_ball\""));
  const auto seed = std::filesystem::path(STC_SOURCE_DIR) / "examples/scenes/hemicylinder.toml";
  try {
    readScene(seed, {"dirichlet[1].component=z"});
    ADD_FAILURE() << "component z accepted in a 2D scene";
  } catch (const InputError& error) {
    EXPECT_THAT(std::string(error.what()), HasSubstr("key 'dirichlet[1].component' = \"z\" is not one of \"x\", \"y\""));
  }
}

}  // namespace stc
