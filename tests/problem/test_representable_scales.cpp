// Scenes whose derived magnitudes leave double precision's range (src/problem/representable_scales.hpp
// and the mesh's measure check, src/mesh/mesh_checks.hpp) are refused by buildProblem, naming the key,
// instead of solving into NaN and Inf outputs; scales well inside the range still build.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/problem/problem.hpp"

namespace {

using ::testing::HasSubstr;

/// The message buildProblem throws for the seed scene changed by `change` ("" if it builds).
std::string refusal(const std::function<void(stc::Scene&)>& change, stc::Scene scene = stc::test::seedScene(21, 5)) {
  change(scene);
  try {
    stc::buildProblem(scene);
  } catch (const stc::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RepresentableScales, AnOverflowingYoungModulusIsRefused) {
  const std::string message = refusal([](stc::Scene& s) { s.material.young = 1e308; });
  EXPECT_THAT(message, HasSubstr("key 'material.young': the stiffness matrix's largest entry"));
  EXPECT_THAT(message, HasSubstr("is not finite"));
  EXPECT_THAT(refusal([](stc::Scene& s) { s.material.young = 1e200; }), HasSubstr("outside [1e-150, 1e150]"));
}

TEST(RepresentableScales, AnUnderflowingYoungModulusIsRefused) {
  EXPECT_THAT(refusal([](stc::Scene& s) { s.material.young = 1e-308; }),
              HasSubstr("key 'material.young': the stiffness matrix's largest entry (∝ young · element size^(d−2)) is"));
}

TEST(RepresentableScales, InstantsThatOverflowAreRefused) {
  // t_k = end · k / (m − 1): end · k overflows from k = 2 on.
  EXPECT_THAT(refusal([](stc::Scene& s) { s.time.end = 1e308; }),
              HasSubstr("key 'time.end': instant t_2 = inf is not finite"));
}

TEST(RepresentableScales, SubnormalInstantsAreRefused) {
  // time.end = 1e-320: instants 5e-323 apart, subnormal, whose ratios keep one or two digits (a run
  // without contact, exit 0, before the check).
  EXPECT_THAT(refusal([](stc::Scene& s) { s.time.end = 1e-320; }),
              HasSubstr("key 'time.end': the time span 9.99989e-321 is outside [1e-150, 1e150]"));
  EXPECT_THAT(refusal([](stc::Scene& s) { s.time.end = 1e-320; }), HasSubstr("choose a larger time.end"));
  EXPECT_EQ(refusal([](stc::Scene& s) { s.time.end = 1e-140; }), "");
}

TEST(RepresentableScales, HugeDisplacementsForcesAndGapsAreRefused) {
  EXPECT_THAT(refusal([](stc::Scene& s) { s.dirichlet[1].history.values = {0.0, 1e308, 1e308}; }),
              HasSubstr("key 'dirichlet[1].values': the largest prescribed displacement is 1e+308, above 1e150"));
  EXPECT_THAT(refusal([](stc::Scene& s) { s.dirichlet[0].history.values = {0.0, 0.0, 1e149}; }),
              HasSubstr("key 'dirichlet[0].values': the force it applies"));
  EXPECT_THAT(refusal([](stc::Scene& s) { s.obstacle.point = Eigen::Vector2d(0.0, -1e200); }),
              HasSubstr("key 'obstacle.point': the largest initial gap is 1e+200"));
  EXPECT_THAT(refusal([](stc::Scene& s) { s.obstacle.point = Eigen::Vector2d(0.0, -1e148); }),
              HasSubstr("key 'obstacle.point': the force of the largest initial gap"));
  EXPECT_THAT(refusal([](stc::Scene& s) { s.loads.push_back({"arc", stc::Component::Y, {{0.0, 1.0}, {0.0, 1e300}}}); }),
              HasSubstr("key 'load[0].values': the largest nodal force"));
}

TEST(RepresentableScales, CoordinatesOutOfRangeAreRefusedAsSuch) {
  for (double radius : {1e150, 1e-150})
    EXPECT_THAT(refusal([radius](stc::Scene& s) { s.mesh.radius = radius; }),
                HasSubstr("state the mesh in other units"))
        << radius;
  EXPECT_THAT(refusal([](stc::Scene& s) { s.mesh.radius = 1e80; }, stc::test::hemisphereScene(3, 5)),
              HasSubstr("the elements' mean volume is"));
}

TEST(RepresentableScales, ScalesWellInsideTheRangeBuild) {
  // Other units: the seed scene in Pa and µm, or GPa and km, builds (each scale within 1e±150).
  EXPECT_EQ(refusal([](stc::Scene& s) { s.material.young = 3e9; }), "");
  EXPECT_EQ(refusal([](stc::Scene& s) {
              s.mesh.radius = 1e6;
              s.obstacle.point = Eigen::Vector2d(0.0, -1.01e6);
              for (auto& d : s.dirichlet)
                for (double& v : d.history.values) v *= 1e6;
            }),
            "");
  EXPECT_EQ(refusal([](stc::Scene& s) { s.time.end = 1e100; }), "");
}
