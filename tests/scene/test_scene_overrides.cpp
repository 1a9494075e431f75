// `--set KEY=VALUE` overrides of the scene reader (docs/interface.md "Command line"): applied before
// validation, so an overridden value obeys every rule, and errors about it say it came from --set.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace stc {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::filesystem::path kSeedFile =
    std::filesystem::path(STC_SOURCE_DIR) / "examples/scenes/hemicylinder.toml";

Scene seedWith(const std::vector<std::string>& overrides) {
  return readScene(kSeedFile, overrides);
}

/// The one-line message of the InputError, with the file-name prefix removed.
std::string errorOf(const std::vector<std::string>& overrides) {
  try {
    seedWith(overrides);
  } catch (const InputError& error) {
    const std::string message = error.what();
    const std::string prefix = kSeedFile.string() + ": ";
    EXPECT_THAT(message, StartsWith(prefix));
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message.substr(std::min(prefix.size(), message.size()));
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(SceneOverrides, FrictionOverrideReplacesTheValue) {
  EXPECT_EQ(seedWith({"contact.friction=0.3"}).contact.friction, 0.3);
}

TEST(SceneOverrides, ArcNodesOverrideReplacesTheValue) {
  EXPECT_EQ(seedWith({"mesh.arc_nodes=401"}).mesh.arc_nodes, 401);
}

TEST(SceneOverrides, PlaneAcceptsAQuotedStringOrABareWord) {
  EXPECT_EQ(seedWith({"model.plane=\"stress\""}).plane, PlaneModel::Stress);
  EXPECT_EQ(seedWith({"model.plane=stress"}).plane, PlaneModel::Stress);
  EXPECT_EQ(seedWith({"solver.name=latin-pgd"}).solver.strategy, stc::Strategy::LatinPgd);
}

TEST(SceneOverrides, TopLevelKeyCanBeOverridden) {
  EXPECT_EQ(seedWith({"name=finer"}).name, "finer");
}

TEST(SceneOverrides, LaterOverrideWins) {
  EXPECT_EQ(seedWith({"contact.friction=0.3", "contact.friction = 0.4"}).contact.friction, 0.4);
}

TEST(SceneOverrides, DirichletEntryIsAddressedByIndex) {
  const Scene s = seedWith({"dirichlet[1].values=[0.0, -0.02, -0.2]"});
  EXPECT_EQ(s.dirichlet[1].history.values, (std::vector<double>{0.0, -0.02, -0.2}));
  EXPECT_EQ(s.dirichlet[0].history.values, (std::vector<double>{0.0, 0.0, 0.05}));
}

TEST(SceneOverrides, ArrayEntryIsAddressedByIndex) {
  EXPECT_EQ(seedWith({"obstacle.point[1]=-1.02"}).obstacle.point.y(), -1.02);
}

TEST(SceneOverrides, MissingOptionalSectionIsCreated) {
  const Scene s = seedWith({"output.frames=false", "time.end=2"});
  EXPECT_FALSE(s.output.frames);
  EXPECT_EQ(s.time.end, 2.0);
}

TEST(SceneOverrides, ParametersJsonHasTheOverriddenValue) {
  // 0.25 is exact in binary: toml++'s JSON writes floats with 17 digits (0.3 as
  // 0.29999999999999999).
  EXPECT_THAT(seedWith({"contact.friction=0.25"}).parameters_json,
              HasSubstr("\"friction\" : 0.25"));
}

TEST(SceneOverrides, UnknownKeyIsAnErrorThatMentionsSet) {
  const std::string message = errorOf({"contact.frictoin=0.3"});
  EXPECT_THAT(message, StartsWith("unknown key 'contact.frictoin'"));
  EXPECT_THAT(message, HasSubstr("(from --set contact.frictoin=0.3)"));
}

TEST(SceneOverrides, UnknownSectionIsAnErrorThatMentionsSet) {
  const std::string message = errorOf({"solvr.tolerance=1e-8"});
  EXPECT_THAT(message, StartsWith("unknown key 'solvr'"));
  EXPECT_THAT(message, HasSubstr("(from --set solvr.tolerance=1e-8)"));
}

TEST(SceneOverrides, OverriddenValueIsValidatedAndMentionsSet) {
  EXPECT_EQ(errorOf({"material.poisson=0.5"}),
            "key 'material.poisson' = 0.5 is out of range: must be in [-0.999999, 0.4999995] (1 + ν and 1 - 2ν at least 1e-6) "
            "(from --set material.poisson=0.5)");
  EXPECT_THAT(errorOf({"time.steps=2.5"}),
              StartsWith("key 'time.steps' must be an integer, got a float (from --set"));
  EXPECT_THAT(errorOf({"contact.friction=lots"}),
              StartsWith("key 'contact.friction' must be a number, got a string (from --set"));
  EXPECT_THAT(errorOf({"dirichlet[1].values=[0, 1]"}),
              StartsWith("key 'dirichlet[1].values' has 2 entries but"));
}

TEST(SceneOverrides, MissingArrayEntryIsAnError) {
  EXPECT_EQ(errorOf({"dirichlet[2].values=[0, 0, 0]"}),
            "--set dirichlet[2].values=[0, 0, 0]: 'dirichlet' has 2 entries, so 'dirichlet[2]' "
            "does not exist");
  EXPECT_THAT(errorOf({"load[0].values=[1]"}), HasSubstr("'load' does not exist"));
}

TEST(SceneOverrides, MalformedOverridesAreErrors) {
  EXPECT_THAT(errorOf({"contact.friction"}), HasSubstr("expected KEY=VALUE"));
  EXPECT_THAT(errorOf({"contact..friction=1"}), HasSubstr("malformed key"));
  EXPECT_THAT(errorOf({"contact.friction="}), HasSubstr("missing value"));
  EXPECT_THAT(errorOf({"contact={friction = 1}"}), HasSubstr("not a table"));
  EXPECT_THAT(errorOf({"name.first=x"}), HasSubstr("'name' is not a table"));
}

// An index too large for size_t made std::stoul throw std::out_of_range, which escaped the reader
// as an internal failure (exit 3) instead of an input error (found with the fuzz target's "#set").
TEST(SceneOverrides, IndexTooLargeForAnyArrayIsAMalformedKey) {
  EXPECT_THAT(errorOf({"dirichlet[99999999999999999999999].values=[1]"}),
              HasSubstr("dirichlet[99999999999999999999999].values=[1]: malformed key"));
}

}  // namespace
}  // namespace stc
