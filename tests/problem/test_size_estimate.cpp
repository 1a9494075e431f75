// The size of a problem before it is built and the memory its solve needs
// (src/problem/size_estimate.hpp): the generators' node counts exactly, the interface rows, and a
// scene far beyond any machine refused naming its size keys, before a mesh is built.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/core/memory.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/problem/size_estimate.hpp"
#include "stcontact/scene/scene_reader.hpp"

using ::testing::HasSubstr;

TEST(SizeEstimate, CountsTheNodesAndTheInterfaceRowsOfTheProblemItWillBuild) {
  for (const stc::Scene& scene : {stc::test::seedScene(101, 21), stc::test::hemisphereScene(4, 21)}) {
    const stc::SizeEstimate e = stc::estimateSize(scene);
    const stc::Problem p = stc::buildProblem(scene);
    EXPECT_EQ(e.nodes, p.numNodes());
    // Potential contact nodes: the generator's arc or curved surface, a few of which (the corners,
    // the rim) are driven and left out of the interface.
    EXPECT_GE(e.contact_rows, p.contact.rows());
    EXPECT_LE(e.contact_rows, 2.0 * p.contact.rows() + 8.0);
    EXPECT_GT(e.bytes, 0.0);
  }
}

TEST(SizeEstimate, ASceneBeyondTheMachineIsRefusedBeforeItsMeshIsBuilt) {
  stc::Scene huge = stc::test::seedScene(101, 21);
  huge.time.steps = 100000000;  // 10^8 instants: 1.6e12 bytes of interface histories
  try {
    stc::buildProblem(huge);
    FAIL() << "10^8 instants accepted";
  } catch (const stc::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("does not fit in memory"));
    EXPECT_THAT(e.what(), HasSubstr("time.steps = 100000000"));
  }
  stc::Scene wide = stc::test::seedScene(2147483647, 21);  // overflowed the generator's numbering
  EXPECT_THROW(stc::requireFitsInMemory(wide), stc::InputError);
  EXPECT_NO_THROW(stc::requireFitsInMemory(stc::test::seedScene(1601, 201)));
}

// The estimate counts what every solve holds, not a direct factor's fill (its analysis checks that):
// the fretting history at 1.07M dofs and 2001 instants, which CG + GAMG solves, fits a 24 GB
// machine; with the 3D fill (20 times K's entries) it took 27.8 GB and was refused.
TEST(SizeEstimate, ASceneAnIterativeBackendSolvesIsNotRefusedForADirectFactorsFill) {
  const stc::Scene fretting = stc::readScene(std::filesystem::path(STC_SOURCE_DIR) /
                                                 "examples/scenes/hemisphere_fretting.toml",
                                             {"mesh.divisions=44"});
  const stc::SizeEstimate e = stc::estimateSize(fretting);
  EXPECT_EQ(fretting.time.steps, 2001);
  EXPECT_GT(3.0 * e.nodes, 1.0e6);  // 10⁶ dofs
  EXPECT_LT(e.bytes, 24.0e9);
}

TEST(Memory, TheAvailableMemoryIsPositiveAndTheTextReadable) {
  EXPECT_GT(stc::availableMemoryBytes(), 0.0);
  EXPECT_EQ(stc::bytesText(2.5e9), "2.5 GB");
  EXPECT_EQ(stc::bytesText(3.2e8), "320 MB");
}
