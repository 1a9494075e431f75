// The rigid motions a scene's Dirichlet conditions leave free (src/problem/rigid_motions.hpp): every
// motion of a body held nowhere, none of the example scenes' bodies, and exactly the ones the
// conditions miss in between, each named; buildProblem refuses a body that can move rigidly.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/problem/rigid_motions.hpp"

namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using Strings = std::vector<std::string>;

/// The free motions of `scene`'s body when the dofs its [[dirichlet]] entries name are prescribed.
Strings freeMotions(const stc::Scene& scene) {
  const stc::BodyMesh body = stc::buildBodyMesh(scene.mesh, scene.dimension);
  const int d = stc::dimensionOf(body);
  std::vector<char> prescribed(static_cast<std::size_t>(d * stc::numNodes(body)), 0);
  for (const stc::DirichletSpec& spec : scene.dirichlet) {
    const int component = stc::componentIndex(spec.component);
    const std::vector<int>& nodes =
        std::visit([&](const auto& mesh) -> const std::vector<int>& { return mesh.group(spec.boundary).nodes; }, body);
    for (int node : nodes) prescribed[static_cast<std::size_t>(d * node + component)] = 1;
  }
  return stc::freeRigidMotions(body, prescribed);
}

stc::Scene withDirichlet(stc::Scene scene, std::vector<stc::DirichletSpec> kept) {
  scene.dirichlet = std::move(kept);
  return scene;
}

}  // namespace

TEST(RigidMotions, TheExampleBodiesAreHeld) {
  EXPECT_TRUE(freeMotions(stc::test::seedScene(21, 5)).empty());
  EXPECT_TRUE(freeMotions(stc::test::hemisphereScene(3, 5)).empty());
}

TEST(RigidMotions, ABodyHeldNowhereCanMoveEveryWay) {
  EXPECT_THAT(freeMotions(withDirichlet(stc::test::seedScene(21, 5), {})),
              ElementsAre("translation along x", "translation along y", "rotation about z"));
  EXPECT_EQ(freeMotions(withDirichlet(stc::test::hemisphereScene(3, 5), {})).size(), 6u);
}

TEST(RigidMotions, TheMotionsTheConditionsMissAreNamed) {
  const stc::Scene seed = stc::test::seedScene(21, 5);
  EXPECT_THAT(freeMotions(withDirichlet(seed, {seed.dirichlet[1]})), ElementsAre("translation along x"));  // y only
  // The top face held along z alone: it cannot tilt, but it can slide and turn in its plane.
  const stc::Scene ball = stc::test::hemisphereScene(3, 5);
  Strings free = freeMotions(withDirichlet(ball, {ball.dirichlet[2]}));
  std::sort(free.begin(), free.end());
  // x and y translate freely in any combination: the two null vectors may mix them.
  ASSERT_EQ(free.size(), 3u);
  EXPECT_EQ(free[0], "rotation about z");
  EXPECT_THAT(free[1], HasSubstr("translation along"));
  EXPECT_THAT(free[2], HasSubstr("translation along"));
  EXPECT_EQ(free[1].find("rotation"), std::string::npos);
  EXPECT_EQ(free[2].find("rotation"), std::string::npos);
}

TEST(RigidMotions, BuildProblemRefusesAFreeBodyNamingTheMotionAndTheBoundaries) {
  const stc::Scene seed = stc::test::seedScene(21, 5);
  try {
    stc::buildProblem(withDirichlet(seed, {seed.dirichlet[1]}));
    FAIL() << "a body free to translate along x was accepted";
  } catch (const stc::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("free to move rigidly (translation along x)"));
    EXPECT_THAT(e.what(), HasSubstr("'arc', 'top'"));
  }
}
