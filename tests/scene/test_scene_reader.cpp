// Scene reader: the seed scene reads with every value, and every rule broken gives one InputError
// whose one-line message starts with the scene file and names the key by its dotted path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/missing_file_error.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace stc {
namespace {

using ::testing::AllOf;
using ::testing::EndsWith;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// The seed scene of docs/interface.md "Scene file", verbatim.
const std::string kSeed = R"(name = "hemicylinder"
[model]
plane = "strain"
[mesh]
generator = "half_disc"
radius = 1.0
arc_nodes = 101
[material]
young = 3000.0
poisson = 0.3
[obstacle]
type = "plane"
point = [0.0, -1.01]
normal = [0.0, 1.0]
[contact]
boundary = "arc"
friction = 0.15
[time]
steps = 201
[[dirichlet]]
boundary = "top"
component = "x"
times  = [0.0, 0.2, 1.0]
values = [0.0, 0.0, 0.05]
[[dirichlet]]
boundary = "top"
component = "y"
times  = [0.0, 0.2, 1.0]
values = [0.0, -0.01, -0.11]
[solver]
name = "fas-apriori"
tolerance = 1e-6
)";

const std::filesystem::path kSource = "hemicylinder.toml";

/// The seed with the first occurrence of `from` replaced by `to`.
std::string seedWith(const std::string& from, const std::string& to) {
  std::string text = kSeed;
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "the seed has no '" << from << "'";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// The message of the InputError that parsing throws; checks that it is one line and starts
/// with the file name.
std::string errorOf(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parseScene(text, kSource, overrides);
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_THAT(message, StartsWith("hemicylinder.toml"));
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

TEST(SceneReader, ExampleSeedSceneHasEveryValueOfInterfaceMd) {
  const auto file = std::filesystem::path(STC_SOURCE_DIR) / "examples/scenes/hemicylinder.toml";
  const Scene s = readScene(file);
  EXPECT_EQ(s.name, "hemicylinder");
  EXPECT_EQ(s.source, file);
  EXPECT_EQ(s.plane, PlaneModel::Strain);
  EXPECT_EQ(s.mesh.generator, "half_disc");
  EXPECT_TRUE(s.mesh.file.empty());
  EXPECT_EQ(s.mesh.radius, 1.0);
  EXPECT_EQ(s.mesh.arc_nodes, 101);
  EXPECT_EQ(s.mesh.grading, MeshSpec{}.grading);
  EXPECT_EQ(s.material.young, 3000.0);
  EXPECT_EQ(s.material.poisson, 0.3);
  EXPECT_EQ(s.obstacle.type, ObstacleType::Plane);
  EXPECT_EQ(s.obstacle.point, Eigen::Vector2d(0.0, -1.01));
  EXPECT_EQ(s.obstacle.normal, Eigen::Vector2d(0.0, 1.0));
  EXPECT_EQ(s.contact.boundary, "arc");
  EXPECT_EQ(s.contact.friction, 0.15);
  EXPECT_FALSE(s.contact.length_scale.has_value());
  EXPECT_EQ(s.time.steps, 201);
  EXPECT_EQ(s.time.end, 1.0);
  ASSERT_EQ(s.dirichlet.size(), 2u);
  EXPECT_EQ(s.dirichlet[0].boundary, "top");
  EXPECT_EQ(s.dirichlet[0].component, Component::X);
  EXPECT_EQ(s.dirichlet[0].history.times, (std::vector<double>{0.0, 0.2, 1.0}));
  EXPECT_EQ(s.dirichlet[0].history.values, (std::vector<double>{0.0, 0.0, 0.05}));
  EXPECT_EQ(s.dirichlet[1].boundary, "top");
  EXPECT_EQ(s.dirichlet[1].component, Component::Y);
  EXPECT_EQ(s.dirichlet[1].history.times, (std::vector<double>{0.0, 0.2, 1.0}));
  EXPECT_EQ(s.dirichlet[1].history.values, (std::vector<double>{0.0, -0.01, -0.11}));
  EXPECT_TRUE(s.loads.empty());
  EXPECT_EQ(s.solver.strategy, stc::Strategy::FasApriori);
  EXPECT_EQ(s.solver.tolerance(), 1e-6);
  EXPECT_EQ(s.solver.latin.stop.max_iterations, 2000);
  EXPECT_EQ(s.search_direction.scale, 4.0);
  EXPECT_EQ(s.solver.latin.relaxation, 1.0);
  EXPECT_TRUE(s.output.frames);
  EXPECT_EQ(s.output.format, OutputFormat::Hdf5);
  EXPECT_EQ(s.output.frame_stride, 0);
  EXPECT_EQ(s.output.field_precision, FieldPrecision::Float32);
  EXPECT_EQ(s.output.contact_csv, ContactCsv::Auto);
}

TEST(SceneReader, ExampleSeedSceneEqualsTheSeedOfInterfaceMd) {
  const auto file = std::filesystem::path(STC_SOURCE_DIR) / "examples/scenes/hemicylinder.toml";
  EXPECT_EQ(readScene(file).parameters_json, parseScene(kSeed, kSource).parameters_json);
}

/// The seed with every optional key given a non-default value.
std::string seedWithEveryOptionalKey() {
  std::string text = seedWith("plane = \"strain\"", "plane = \"stress\"");
  text.replace(text.find("arc_nodes = 101"), 15, "arc_nodes = 11\ngrading = 1.5");
  text.replace(text.find("friction = 0.15"), 15, "friction = 0.15\nlength_scale = 2");
  text.replace(text.find("steps = 201"), 11, "steps = 3\nend = 2.5");
  text.replace(text.find("tolerance = 1e-6"), 16, R"(tolerance = 1e-8
max_iterations = 50
search_scale = 2
relaxation = 0.5
[output]
frames = false
format = "vtu"
frame_stride = 5
field_precision = "float64"
contact_csv = "always"
[[load]]
boundary = "top"
component = "y"
times = [0.5]
values = [-2.0])");
  return text;
}

TEST(SceneReader, OptionalKeysOverrideTheirDefaults) {
  const Scene s = parseScene(seedWithEveryOptionalKey(), kSource);
  EXPECT_EQ(s.plane, PlaneModel::Stress);
  EXPECT_EQ(s.mesh.arc_nodes, 11);
  EXPECT_EQ(s.mesh.grading, 1.5);
  EXPECT_EQ(s.contact.length_scale, 2.0);
  EXPECT_EQ(s.time.steps, 3);
  EXPECT_EQ(s.time.end, 2.5);
  EXPECT_EQ(s.solver.tolerance(), 1e-8);
  EXPECT_EQ(s.solver.fas_apriori.fas.stop.max_iterations, 50);
  EXPECT_EQ(s.search_direction.scale, 2.0);
  EXPECT_EQ(s.solver.latin.relaxation, 0.5);
  EXPECT_FALSE(s.output.frames);
  EXPECT_EQ(s.output.format, OutputFormat::Vtu);
  EXPECT_EQ(s.output.frame_stride, 5);
  EXPECT_EQ(s.output.field_precision, FieldPrecision::Float64);
  EXPECT_EQ(s.output.contact_csv, ContactCsv::Always);
  ASSERT_EQ(s.loads.size(), 1u);
  EXPECT_EQ(s.loads[0].boundary, "top");
  EXPECT_EQ(s.loads[0].component, Component::Y);
  EXPECT_EQ(s.loads[0].history.times, std::vector<double>{0.5});
  EXPECT_EQ(s.loads[0].history.values, std::vector<double>{-2.0});
}

TEST(SceneReader, OmittedOptionalSectionsTakeDefaults) {
  std::string text = seedWith("[model]\nplane = \"strain\"\n", "");
  text = text.substr(0, text.find("[solver]"));
  const Scene s = parseScene(text, kSource);
  EXPECT_EQ(s.plane, PlaneModel::Strain);
  EXPECT_EQ(s.solver.strategy, stc::Strategy::FasApriori);
  EXPECT_EQ(s.solver.tolerance(), 1e-6);
  EXPECT_TRUE(s.output.frames);
}

TEST(SceneReader, IntegerIsAcceptedWhereAFloatIsExpected) {
  const Scene s = parseScene(seedWith("young = 3000.0", "young = 3000"), kSource);
  EXPECT_EQ(s.material.young, 3000.0);
}

TEST(SceneReader, ObstacleNormalIsNormalised) {
  const Scene s = parseScene(seedWith("normal = [0.0, 1.0]", "normal = [3, 4]"), kSource);
  EXPECT_NEAR(s.obstacle.normal.x(), 0.6, 1e-15);
  EXPECT_NEAR(s.obstacle.normal.y(), 0.8, 1e-15);
}

TEST(SceneReader, HistoryWithOneInstantIsAccepted) {
  const Scene s = parseScene(
      seedWith("times  = [0.0, 0.2, 1.0]\nvalues = [0.0, 0.0, 0.05]", "times = [0]\nvalues = [0]"),
      kSource);
  EXPECT_EQ(s.dirichlet[0].history.times.size(), 1u);
}

TEST(SceneReader, RelativeMeshFileIsResolvedAgainstTheSceneFolder) {
  const std::string text = seedWith("generator = \"half_disc\"\nradius = 1.0\narc_nodes = 101",
                                    "file = \"../meshes/part.msh\"");
  const Scene s = parseScene(text, "/data/study/scenes/cut.toml");
  EXPECT_TRUE(s.mesh.generator.empty());
  EXPECT_EQ(s.mesh.file, std::filesystem::path("/data/study/meshes/part.msh"));
  const Scene t = parseScene(text, "cut.toml");
  EXPECT_EQ(t.mesh.file, std::filesystem::path("../meshes/part.msh"));
}

TEST(SceneReader, AbsoluteMeshFileIsKept) {
  const Scene s = parseScene(seedWith("generator = \"half_disc\"\nradius = 1.0\narc_nodes = 101",
                                      "file = \"/meshes/part.msh\""),
                             "/data/cut.toml");
  EXPECT_EQ(s.mesh.file, std::filesystem::path("/meshes/part.msh"));
}

TEST(SceneReader, ParametersJsonIsTheTableAsAJsonObject) {
  const std::string json = parseScene(kSeed, kSource).parameters_json;
  ASSERT_FALSE(json.empty());
  EXPECT_EQ(json.front(), '{');
  EXPECT_EQ(json.back(), '}');
  EXPECT_THAT(json, HasSubstr("\"name\" : \"hemicylinder\""));
  EXPECT_THAT(json, HasSubstr("\"young\" : 3000.0"));
  EXPECT_THAT(json, HasSubstr("\"steps\" : 201"));
  EXPECT_THAT(json, HasSubstr("\"dirichlet\" : ["));
}

TEST(SceneReader, MissingFileIsAnInputErrorNamingIt) {
  try {
    readScene("/nonexistent/folder/gone.toml");
    FAIL() << "no MissingFileError";
  } catch (const MissingFileError& error) {  // an InputError that also carries the path
    EXPECT_EQ(std::string(error.what()),
              "/nonexistent/folder/gone.toml: cannot open the scene file (missing or unreadable)");
    EXPECT_EQ(error.path(), "/nonexistent/folder/gone.toml");
  }
}

TEST(SceneReader, AFolderIsAnInputErrorButNotAMissingFile) {
  const std::string folder = std::filesystem::temp_directory_path().string();
  try {
    readScene(folder);
    FAIL() << "no InputError";
  } catch (const MissingFileError&) {
    FAIL() << "a folder exists: not a missing file";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), EndsWith(": is a folder, not a scene file"));
  }
}

// --- Errors: every message names the key by its dotted path and the rule. ---

TEST(SceneReaderErrors, UnknownTopLevelKeyIsNamed) {
  EXPECT_THAT(errorOf("colour = \"red\"\n" + kSeed),
              StartsWith("hemicylinder.toml: unknown key 'colour'"));
}

TEST(SceneReaderErrors, UnknownKeyInASectionIsNamedWithItsSection) {
  EXPECT_THAT(errorOf(seedWith("young = 3000.0", "youngs = 3000.0")),
              StartsWith("hemicylinder.toml: unknown key 'material.youngs'"));
}

TEST(SceneReaderErrors, UnknownKeyInSolverIsAnError) {
  EXPECT_THAT(errorOf(kSeed + "coarse_rank = 4\n"),
              StartsWith("hemicylinder.toml: unknown key 'solver.coarse_rank'"));
}

TEST(SceneReaderErrors, UnknownKeyInADirichletEntryIsNamedWithItsIndex) {
  EXPECT_THAT(errorOf(seedWith("component = \"y\"", "component = \"y\"\nscale = 2")),
              StartsWith("hemicylinder.toml: unknown key 'dirichlet[1].scale'"));
}

TEST(SceneReaderErrors, StringWhereAnIntegerIsExpectedIsATypeError) {
  EXPECT_EQ(errorOf(seedWith("steps = 201", "steps = \"201\"")),
            "hemicylinder.toml: key 'time.steps' must be an integer, got a string");
}

TEST(SceneReaderErrors, FloatWhereAnIntegerIsExpectedIsATypeError) {
  EXPECT_EQ(errorOf(seedWith("steps = 201", "steps = 201.0")),
            "hemicylinder.toml: key 'time.steps' must be an integer, got a float");
}

TEST(SceneReaderErrors, StringWhereANumberIsExpectedIsATypeError) {
  EXPECT_EQ(errorOf(seedWith("friction = 0.15", "friction = \"0.15\"")),
            "hemicylinder.toml: key 'contact.friction' must be a number, got a string");
}

TEST(SceneReaderErrors, SectionThatIsNotATableIsATypeError) {
  EXPECT_EQ(errorOf("model = 3\n" + seedWith("[model]\nplane = \"strain\"\n", "")),
            "hemicylinder.toml: key 'model' must be a table, got an integer");
}

TEST(SceneReaderErrors, DirichletAsASingleTableIsATypeError) {
  std::string text = kSeed.substr(0, kSeed.find("[[dirichlet]]"));
  text += "[dirichlet]\nboundary = \"top\"\n";
  EXPECT_THAT(errorOf(text), StartsWith("hemicylinder.toml: key 'dirichlet' must be an array of "
                                        "tables ([[dirichlet]]), got a table"));
}

TEST(SceneReaderErrors, MissingRequiredKeyIsNamed) {
  EXPECT_EQ(errorOf(seedWith("friction = 0.15\n", "")),
            "hemicylinder.toml: missing required key 'contact.friction'");
  EXPECT_EQ(errorOf(seedWith("name = \"hemicylinder\"\n", "")),
            "hemicylinder.toml: missing required key 'name'");
}

TEST(SceneReaderErrors, MissingRequiredSectionIsNamed) {
  EXPECT_EQ(errorOf(seedWith("[material]\nyoung = 3000.0\npoisson = 0.3\n", "")),
            "hemicylinder.toml: missing required key 'material'");
}

TEST(SceneReaderErrors, PoissonRatioOfOneHalfIsOutOfRange) {
  EXPECT_EQ(
      errorOf(seedWith("poisson = 0.3", "poisson = 0.5")),
      "hemicylinder.toml: key 'material.poisson' = 0.5 is out of range: must be in [-0.999999, 0.4999995] (1 + ν and 1 - 2ν at least 1e-6)");
}

TEST(SceneReaderErrors, PoissonRatioOfMinusOneIsOutOfRange) {
  EXPECT_EQ(errorOf(seedWith("poisson = 0.3", "poisson = -1")),
            "hemicylinder.toml: key 'material.poisson' = -1 is out of range: must be in [-0.999999, 0.4999995] (1 + ν and 1 - 2ν at least 1e-6)");
}

TEST(SceneReaderErrors, NonPositiveYoungModulusIsOutOfRange) {
  EXPECT_EQ(errorOf(seedWith("young = 3000.0", "young = 0.0")),
            "hemicylinder.toml: key 'material.young' = 0 is out of range: must be > 0");
  EXPECT_THAT(errorOf(seedWith("young = 3000.0", "young = -5")),
              StartsWith("hemicylinder.toml: key 'material.young' = -5 is out of range"));
}

TEST(SceneReaderErrors, NegativeFrictionIsOutOfRange) {
  EXPECT_EQ(errorOf(seedWith("friction = 0.15", "friction = -0.1")),
            "hemicylinder.toml: key 'contact.friction' = -0.1 is out of range: must be >= 0");
}

TEST(SceneReaderErrors, SingleTimeStepIsOutOfRange) {
  EXPECT_EQ(errorOf(seedWith("steps = 201", "steps = 1")),
            "hemicylinder.toml: key 'time.steps' = 1 is out of range: must be >= 2");
}

TEST(SceneReaderErrors, OtherRangesAreChecked) {
  EXPECT_THAT(errorOf(seedWith("radius = 1.0", "radius = 0")), HasSubstr("'mesh.radius' = 0"));
  EXPECT_THAT(errorOf(seedWith("arc_nodes = 101", "arc_nodes = 101\ngrading = 0.9")),
              HasSubstr("'mesh.grading' = 0.9"));
  EXPECT_THAT(errorOf(seedWith("arc_nodes = 101", "arc_nodes = 2")),
              HasSubstr("'mesh.arc_nodes' = 2"));
  EXPECT_THAT(errorOf(seedWith("steps = 201", "steps = 201\nend = 0")),
              HasSubstr("'time.end' = 0"));
  EXPECT_THAT(errorOf(kSeed + "relaxation = 1.5\n"), HasSubstr("'solver.relaxation' = 1.5"));
  EXPECT_THAT(errorOf(kSeed + "max_iterations = 0\n"), HasSubstr("'solver.max_iterations' = 0"));
  EXPECT_THAT(errorOf(seedWith("tolerance = 1e-6", "tolerance = 0")),
              HasSubstr("'solver.tolerance' = 0"));
  EXPECT_THAT(errorOf(kSeed + "[output]\nframe_stride = -1\n"), HasSubstr("'output.frame_stride' = -1"));
  EXPECT_THAT(errorOf(kSeed + "[output]\nvtu = false\n"),
              HasSubstr("unknown key 'output.vtu' (allowed in [output]: frames, format, frame_stride, field_precision, "
                        "contact_csv); renamed 'output.frames' in version 0.4"));
  EXPECT_THAT(errorOf(kSeed + "[output]\nformat = \"exodus\"\n"),
              HasSubstr("'output.format' = \"exodus\" is not one of \"hdf5\", \"vtu\""));
  EXPECT_THAT(errorOf(kSeed + "[output]\nfield_precision = \"float16\"\n"),
              HasSubstr("'output.field_precision' = \"float16\" is not one of \"float32\", \"float64\""));
  EXPECT_THAT(errorOf(seedWith("friction = 0.15", "friction = 0.15\nlength_scale = -1")),
              HasSubstr("'contact.length_scale' = -1"));
}

TEST(SceneReader, EveryOutputKeyOfTheCodeIsDocumentedAndNoOther) {
  // docs/scene_format.md lists each key as "| `output.KEY` | ...".
  std::ifstream page(std::string(STC_SOURCE_DIR) + "/docs/scene_format.md");
  ASSERT_TRUE(page) << "docs/scene_format.md";
  std::set<std::string> documented, code;
  const std::regex row(R"(^\| `output\.([a-z_0-9]+)` \|)");
  for (std::string line; std::getline(page, line);)
    if (std::smatch m; std::regex_search(line, m, row)) documented.insert(m[1]);
  OutputSpec spec;
  OutputSpec::fields(spec, [&](const char* key, const auto&, const auto&) { code.insert(key); });
  EXPECT_EQ(documented, code);
  EXPECT_EQ(code, (std::set<std::string>{"frames", "format", "frame_stride", "field_precision", "contact_csv"}));
}

TEST(SceneReader, FasKeysAreRead) {
  const Scene s = parseScene(kSeed + "pre_relaxations = 2\npost_relaxations = 0\ncoarse_iterations = 7\n"
                                     "residual_vectors = 5\nsvd_modes = 4\npgd_max_modes = 12\n"
                                     "pgd_increment_modes = 7\npgd_gap_share = 0.2\ncoarse_start = \"mismatch\"\n"
                                     "adapt_coarse_iterations = false\ncoarse_anderson = 0\nsafeguard_growth = 1\n"
                                     "pgd_anticipate = false\ncoarse_zone = false\nreduce_interface = false\n"
                                     "nested_instants = 0\nzone_margin = 0.25\nzone_reach_margin = 0.01\n"
                                     "zone_rounds = 2\nzone_whole_share = 0.5\nnested_tolerance = 1e-5\n"
                                     "nested_on_iterative = true\n",
                             kSource);
  const stc::fas::FasAprioriOptions& apriori = s.solver.fas_apriori;
  const stc::fas::FasAposterioriOptions& aposteriori = s.solver.fas_aposteriori;
  for (const stc::fas::FasOptions* fas : {&apriori.fas, &aposteriori.fas}) {  // a key of both FAS strategies
    EXPECT_EQ(fas->pre_relaxations, 2);
    EXPECT_EQ(fas->post_relaxations, 0);
    EXPECT_EQ(fas->coarse_iterations, 7);
    EXPECT_EQ(fas->start, stc::fas::CoarseStart::InterfaceMismatch);
    EXPECT_FALSE(fas->adapt_coarse_iterations);
    EXPECT_FALSE(fas->coarse_zone);
    EXPECT_EQ(fas->coarse_anderson, 0);
    EXPECT_EQ(fas->safeguard_growth, 1.0);
  }
  EXPECT_EQ(aposteriori.basis.residual_vectors, 5);
  EXPECT_EQ(aposteriori.basis.svd_modes, 4);
  EXPECT_EQ(apriori.basis.modes, 12);
  EXPECT_EQ(apriori.basis.increment_modes, 7);
  EXPECT_FALSE(apriori.basis.anticipate);
  EXPECT_EQ(apriori.stage.gap_share, 0.2);
  EXPECT_EQ(s.solver.latin_pgd.stage.gap_share, 0.2);  // a key of latin-pgd and fas-apriori
  EXPECT_FALSE(apriori.zone.enabled);
  EXPECT_EQ(apriori.zone.margin, 0.25);
  EXPECT_EQ(apriori.zone.reach_margin, 0.01);
  EXPECT_EQ(apriori.zone.rounds, 2);
  EXPECT_EQ(apriori.zone.whole_share, 0.5);
  EXPECT_EQ(apriori.nested.instants, 0);
  EXPECT_EQ(apriori.nested.tolerance, 1e-5);
  EXPECT_TRUE(apriori.nested.on_iterative);
}

TEST(SceneReader, OmittedFasKeysTakeTheOptionsDefaults) {
  const stc::SolverSpec read = parseScene(kSeed, kSource).solver;
  const stc::fas::FasAprioriOptions defaults;
  EXPECT_EQ(read.fas_apriori.fas.coarse_anderson, defaults.fas.coarse_anderson);
  EXPECT_EQ(read.fas_apriori.fas.coarse_zone, defaults.fas.coarse_zone);
  EXPECT_EQ(read.fas_apriori.fas.adapt_coarse_iterations, defaults.fas.adapt_coarse_iterations);
  EXPECT_FALSE(read.fas_apriori.fas.safeguard_growth);  // the dimension's default
  EXPECT_EQ(read.fas_apriori.basis.anticipate, defaults.basis.anticipate);
  EXPECT_EQ(read.fas_apriori.zone.enabled, defaults.zone.enabled);
  EXPECT_EQ(read.fas_apriori.nested.instants, defaults.nested.instants);
  EXPECT_FALSE(read.fas_apriori.nested.on_iterative);
  EXPECT_EQ(parseScene(kSeed + "nested_instants = 51\n", kSource).solver.fas_apriori.nested.instants, 51);
}

TEST(SceneReader, AKeyOfSeveralStrategiesSetsEachOfThem) {
  const stc::SolverSpec s = parseScene(kSeed + "max_iterations = 77\n", kSource).solver;
  for (const auto& [name, strategy] : stc::kStrategies) {
    if (strategy == stc::Strategy::Incremental) {
      EXPECT_EQ(s.stopping(strategy), nullptr);
      continue;
    }
    ASSERT_NE(s.stopping(strategy), nullptr) << name;
    EXPECT_EQ(s.stopping(strategy)->tolerance, 1e-6) << name;
    EXPECT_EQ(s.stopping(strategy)->max_iterations, 77) << name;
  }
}

TEST(SceneReader, KeysRemovedIn030AreRefusedWithTheReason) {
  // docs/changelog.md: pgd_modes_per_cycle and pgd_seed_share had no effect since 0.2.0.
  for (const char* key : {"pgd_modes_per_cycle = 2\n", "pgd_seed_share = 0.25\n"})
    EXPECT_THAT(errorOf(kSeed + key), HasSubstr("was removed in version 0.3.0")) << key;
}

TEST(SceneReaderErrors, FasRangesAreChecked) {
  EXPECT_THAT(errorOf(kSeed + "pre_relaxations = 0\n"), HasSubstr("'solver.pre_relaxations' = 0"));
  EXPECT_THAT(errorOf(kSeed + "post_relaxations = -1\n"), HasSubstr("'solver.post_relaxations' = -1"));
  EXPECT_THAT(errorOf(kSeed + "coarse_iterations = 0\n"), HasSubstr("'solver.coarse_iterations' = 0"));
  EXPECT_THAT(errorOf(kSeed + "pgd_max_modes = -1\n"), HasSubstr("'solver.pgd_max_modes' = -1"));
  EXPECT_THAT(errorOf(kSeed + "pgd_gap_share = 1\n"), HasSubstr("'solver.pgd_gap_share' = 1"));
  EXPECT_THAT(errorOf(kSeed + "pgd_increment_modes = -1\n"), HasSubstr("'solver.pgd_increment_modes' = -1"));
  EXPECT_THAT(errorOf(kSeed + "pgd_gap_share = 0\n"), HasSubstr("'solver.pgd_gap_share' = 0"));
  EXPECT_THAT(errorOf(kSeed + "pgd_full_share = 0\n"), HasSubstr("'solver.pgd_full_share' = 0"));
  EXPECT_THAT(errorOf(kSeed + "pgd_full_share = 1.5\n"), HasSubstr("'solver.pgd_full_share' = 1.5"));
  EXPECT_THAT(errorOf(kSeed + "coarse_start = \"middle\"\n"), HasSubstr("solver.coarse_start"));
  EXPECT_THAT(errorOf(kSeed + "adapt_coarse_iterations = 1\n"), HasSubstr("solver.adapt_coarse_iterations"));
  EXPECT_THAT(errorOf(kSeed + "pgd_anticipate = \"yes\"\n"), HasSubstr("solver.pgd_anticipate"));
  EXPECT_THAT(errorOf(kSeed + "coarse_zone = 0\n"), HasSubstr("solver.coarse_zone"));
  EXPECT_THAT(errorOf(kSeed + "reduce_interface = 1\n"), HasSubstr("solver.reduce_interface"));
  EXPECT_THAT(errorOf(kSeed + "nested_instants = 1\n"), HasSubstr("'solver.nested_instants' = 1"));
  EXPECT_THAT(errorOf(kSeed + "nested_instants = -2\n"), HasSubstr("'solver.nested_instants' = -2"));
  EXPECT_THAT(errorOf(kSeed + "coarse_anderson = -1\n"), HasSubstr("'solver.coarse_anderson' = -1"));
  EXPECT_THAT(errorOf(kSeed + "safeguard_growth = 0.5\n"), HasSubstr("'solver.safeguard_growth' = 0.5"));
}

TEST(SceneReaderErrors, TimesNotStrictlyIncreasingAreNamed) {
  const std::string text = seedWith("times  = [0.0, 0.2, 1.0]\nvalues = [0.0, -0.01",
                                    "times  = [0.0, 0.2, 0.2]\nvalues = [0.0, -0.01");
  EXPECT_THAT(
      errorOf(text),
      StartsWith("hemicylinder.toml: key 'dirichlet[1].times' must be strictly increasing"));
}

TEST(SceneReaderErrors, TimesAndValuesOfDifferentLengthsAreNamed) {
  EXPECT_THAT(errorOf(seedWith("values = [0.0, -0.01, -0.11]", "values = [0.0, -0.01]")),
              StartsWith("hemicylinder.toml: key 'dirichlet[1].values' has 2 entries but "
                         "'dirichlet[1].times' has 3"));
}

TEST(SceneReaderErrors, NanLiteralIsRejectedNamingTheKey) {
  EXPECT_EQ(errorOf(seedWith("young = 3000.0", "young = nan")),
            "hemicylinder.toml: key 'material.young' = nan is not a finite number");
}

TEST(SceneReaderErrors, InfinityIsRejectedNamingTheKeyAndEntry) {
  EXPECT_EQ(errorOf(seedWith("friction = 0.15", "friction = inf")),
            "hemicylinder.toml: key 'contact.friction' = inf is not a finite number");
  EXPECT_EQ(errorOf(seedWith("point = [0.0, -1.01]", "point = [0.0, -inf]")),
            "hemicylinder.toml: key 'obstacle.point[1]' = -inf is not a finite number");
}

TEST(SceneReaderErrors, UnknownSolverNameIsRejected) {
  EXPECT_THAT(errorOf(seedWith("name = \"fas-apriori\"", "name = \"fas\"")),
              StartsWith("hemicylinder.toml: key 'solver.name' = \"fas\" is not one of \"latin\", "
                         "\"latin-pgd\", \"fas-aposteriori\", \"fas-apriori\", \"incremental\""));
}

TEST(SceneReaderErrors, UnknownKeywordsAreRejected) {
  EXPECT_THAT(errorOf(seedWith("plane = \"strain\"", "plane = \"plain\"")),
              HasSubstr("key 'model.plane' = \"plain\" is not one of"));
  EXPECT_THAT(errorOf(seedWith("component = \"x\"", "component = \"z\"")),
              HasSubstr("key 'dirichlet[0].component' = \"z\" is not one of"));
  EXPECT_THAT(errorOf(seedWith("type = \"plane\"", "type = \"disc\"")),
              HasSubstr("key 'obstacle.type' = \"disc\" is not one of"));
  EXPECT_THAT(errorOf(seedWith("generator = \"half_disc\"", "generator = \"disc\"")),
              HasSubstr("key 'mesh.generator' = \"disc\" is not one of"));
}

TEST(SceneReaderErrors, GeneratorAndFileTogetherAreRejected) {
  EXPECT_THAT(errorOf(seedWith("radius = 1.0", "file = \"part.msh\"\nradius = 1.0")),
              StartsWith("hemicylinder.toml: keys 'mesh.generator' and 'mesh.file' exclude"));
}

TEST(SceneReaderErrors, NeitherGeneratorNorFileIsRejected) {
  EXPECT_EQ(errorOf(seedWith("generator = \"half_disc\"\n", "")),
            "hemicylinder.toml: missing required key 'mesh.generator' or 'mesh.file' (give one)");
}

TEST(SceneReaderErrors, GeneratorKeysWithAMeshFileAreRejected) {
  EXPECT_THAT(errorOf(seedWith("generator = \"half_disc\"", "file = \"part.msh\"")),
              StartsWith("hemicylinder.toml: key 'mesh.radius' applies to generator"));
}

TEST(SceneReaderErrors, ZeroNormalIsRejected) {
  EXPECT_THAT(errorOf(seedWith("normal = [0.0, 1.0]", "normal = [0, 0]")),
              StartsWith("hemicylinder.toml: key 'obstacle.normal' = [0, 0] must be a nonzero"));
}

TEST(SceneReaderErrors, PointWithThreeEntriesIsRejected) {
  EXPECT_EQ(errorOf(seedWith("point = [0.0, -1.01]", "point = [0.0, -1.01, 0.0]")),
            "hemicylinder.toml: key 'obstacle.point' must have 2 entries [x, y], got 3 (a 3D scene needs "
            "'dimension = 3' at its top)");
}

// A cylinder obstacle (the 2D section of a ball) in place of the seed's plane.
std::string seedOnCylinder(const std::string& keys) {
  return seedWith("type = \"plane\"\npoint = [0.0, -1.01]\nnormal = [0.0, 1.0]", "type = \"cylinder\"\n" + keys);
}

TEST(SceneReader, CylinderObstacleIsReadWithItsCentreRadiusAndSide) {
  const Scene outside = parseScene(seedOnCylinder("centre = [0.0, -2.01]\nradius = 1.0"), kSource, {});
  EXPECT_EQ(outside.obstacle.type, ObstacleType::Cylinder);
  EXPECT_EQ(outside.obstacle.centre, Eigen::Vector2d(0.0, -2.01));
  EXPECT_EQ(outside.obstacle.radius, 1.0);
  EXPECT_FALSE(outside.obstacle.inside);
  const Scene seat = parseScene(seedOnCylinder("centre = [0.0, 0.99]\nradius = 2.0\nside = \"inside\""), kSource, {});
  EXPECT_TRUE(seat.obstacle.inside);
}

TEST(SceneReaderErrors, BadCurvedObstaclesAreRejectedWithTheKey) {
  EXPECT_EQ(errorOf(seedOnCylinder("centre = [0.0, -2.01]\nradius = -1.0")),
            "hemicylinder.toml: key 'obstacle.radius' = -1 is out of range: must be > 0");
  EXPECT_EQ(errorOf(seedOnCylinder("centre = [0.0, -2.01, 0.0]\nradius = 1.0")),
            "hemicylinder.toml: key 'obstacle.centre' must have 2 entries [x, y], got 3 (a 3D scene needs "
            "'dimension = 3' at its top)");
  EXPECT_EQ(errorOf(seedOnCylinder("centre = [0.0, -2.01]\nradius = 1.0\nside = \"above\"")),
            "hemicylinder.toml: key 'obstacle.side' = \"above\" is not one of \"outside\", \"inside\"");
  EXPECT_EQ(errorOf(seedOnCylinder("centre = [0.0, -2.01]\nradius = 1.0\nnormal = [0.0, 1.0]")),
            "hemicylinder.toml: key 'obstacle.normal' does not apply to obstacle.type = \"cylinder\" (its keys: "
            "'centre', 'radius', 'side')");
  EXPECT_THAT(errorOf(seedOnCylinder("radius = 1.0")), HasSubstr("'obstacle.centre'"));
  EXPECT_EQ(errorOf(seedWith("type = \"plane\"\npoint = [0.0, -1.01]\nnormal = [0.0, 1.0]",
                             "type = \"sphere\"\ncentre = [0.0, -2.01]\nradius = 1.0")),
            "hemicylinder.toml: key 'obstacle.type' = \"sphere\" needs a 3D scene (a cylinder in 2D)");
  EXPECT_EQ(errorOf(seedWith("normal = [0.0, 1.0]", "normal = [0.0, 1.0]\nradius = 1.0")),
            "hemicylinder.toml: key 'obstacle.radius' does not apply to obstacle.type = \"plane\" (its keys: "
            "'point', 'normal')");
}

// The seed's first Dirichlet history (x of the top) replaced by `history` (its keys, one per line).
std::string seedWithXHistory(const std::string& history) {
  return seedWith("times  = [0.0, 0.2, 1.0]\nvalues = [0.0, 0.0, 0.05]", history);
}

TEST(SceneReader, APeriodicHistoryIsItsPeriodRepeated) {
  // One period of 0.2 (40 steps of 0.005): out and back, three times, then held.
  const Scene s = parseScene(seedWithXHistory("times = [0.1, 0.15, 0.2, 0.25, 0.3]\n"
                                              "values = [0.0, 0.01, 0.0, -0.01, 0.0]\nperiod = 0.2\ncycles = 3"),
                             kSource, {});
  const std::vector<double> times = {0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.5, 0.55, 0.6, 0.65, 0.7};
  const std::vector<double> values = {0.0, 0.01, 0.0, -0.01, 0.0, 0.01, 0.0, -0.01, 0.0, 0.01, 0.0, -0.01, 0.0};
  ASSERT_EQ(s.dirichlet[0].history.times.size(), times.size());
  for (std::size_t i = 0; i < times.size(); ++i) {
    EXPECT_NEAR(s.dirichlet[0].history.times[i], times[i], 1e-15) << i;
    EXPECT_EQ(s.dirichlet[0].history.values[i], values[i]) << i;
  }
  // Points that stop short of the period hold their last value until the next cycle starts.
  const Scene held = parseScene(seedWithXHistory("times = [0.0, 0.05]\nvalues = [0.0, 0.0]\nperiod = 0.1\ncycles = 2"),
                                kSource, {});
  const std::vector<double> held_times = {0.0, 0.05, 0.1, 0.15};
  ASSERT_EQ(held.dirichlet[0].history.times.size(), held_times.size());
  for (std::size_t i = 0; i < held_times.size(); ++i)
    EXPECT_NEAR(held.dirichlet[0].history.times[i], held_times[i], 1e-15) << i;
}

TEST(SceneReaderErrors, BadPeriodicHistoriesAreRejectedWithTheKey) {
  const std::string one = "times = [0.0, 0.1, 0.2]\nvalues = [0.0, 0.01, 0.0]\n";
  EXPECT_EQ(errorOf(seedWithXHistory(one + "period = 0.2")),
            "hemicylinder.toml: key 'dirichlet[0].period' needs 'dirichlet[0].cycles' too (a periodic history "
            "takes both)");
  EXPECT_EQ(errorOf(seedWithXHistory(one + "period = 0.2012\ncycles = 2")),
            "hemicylinder.toml: key 'dirichlet[0].period' = 0.2012 is not a whole number of time steps "
            "(time.end / (time.steps - 1) = 0.005): every cycle must meet the same instants");
  EXPECT_EQ(errorOf(seedWithXHistory(one + "period = -0.2\ncycles = 2")),
            "hemicylinder.toml: key 'dirichlet[0].period' = -0.2 is out of range: must be > 0");
  EXPECT_EQ(errorOf(seedWithXHistory(one + "period = 0.2\ncycles = 0")),
            "hemicylinder.toml: key 'dirichlet[0].cycles' = 0 is out of range: must be >= 1");
  EXPECT_EQ(errorOf(seedWithXHistory(one + "period = 0.1\ncycles = 2")),
            "hemicylinder.toml: key 'dirichlet[0].times' spans 0.2, more than one period (0.1)");
  EXPECT_EQ(errorOf(seedWithXHistory("times = [0.0, 0.1]\nvalues = [0.0, 0.01]\nperiod = 0.2\ncycles = 2")),
            "hemicylinder.toml: key 'dirichlet[0].values' must end on the value it starts with (0, not 0.01) to "
            "repeat");
}

// The seed with one [[load]] entry appended (its keys, one per line).
std::string seedWithLoad(const std::string& keys) { return std::string(kSeed) + "[[load]]\n" + keys + "\n"; }

TEST(SceneReader, PressureAndBodyLoadsAreReadWithTheirKeys) {
  const Scene pressure = parseScene(seedWithLoad("type = \"pressure\"\nboundary = \"arc\"\ntimes = [0]\nvalues = [1]"),
                                    kSource, {});
  ASSERT_EQ(pressure.loads.size(), 1u);
  EXPECT_EQ(pressure.loads[0].kind, LoadKind::Pressure);
  EXPECT_EQ(pressure.loads[0].boundary, "arc");
  const Scene body = parseScene(seedWithLoad("type = \"body\"\ncomponent = \"y\"\ntimes = [0]\nvalues = [-1]"),
                                kSource, {});
  EXPECT_EQ(body.loads[0].kind, LoadKind::Body);
  EXPECT_EQ(body.loads[0].component, Component::Y);
  const Scene force = parseScene(seedWithLoad("boundary = \"arc\"\ncomponent = \"x\"\ntimes = [0]\nvalues = [1]"),
                                 kSource, {});
  EXPECT_EQ(force.loads[0].kind, LoadKind::Force);
}

TEST(SceneReaderErrors, LoadKeysOfAnotherTypeAreRejected) {
  EXPECT_EQ(errorOf(seedWithLoad("type = \"pressure\"\nboundary = \"arc\"\ncomponent = \"x\"\ntimes = [0]\nvalues = [1]")),
            "hemicylinder.toml: key 'load[0].component' does not apply to type = \"pressure\" (along the inward "
            "normal)");
  EXPECT_EQ(errorOf(seedWithLoad("type = \"body\"\nboundary = \"arc\"\ncomponent = \"y\"\ntimes = [0]\nvalues = [1]")),
            "hemicylinder.toml: key 'load[0].boundary' does not apply to type = \"body\" (on the whole body)");
  EXPECT_EQ(errorOf(seedWithLoad("type = \"gravity\"\ncomponent = \"y\"\ntimes = [0]\nvalues = [1]")),
            "hemicylinder.toml: key 'load[0].type' = \"gravity\" is not one of \"force\", \"pressure\", \"body\"");
  EXPECT_THAT(errorOf(seedWith("boundary = \"top\"\ncomponent = \"x\"", "type = \"pressure\"\nboundary = \"top\"\ncomponent = \"x\"")),
              HasSubstr("key 'dirichlet[0].type' applies to [[load]] entries only"));
}

TEST(SceneReaderErrors, EmptyBoundaryNameIsRejected) {
  EXPECT_EQ(errorOf(seedWith("boundary = \"arc\"", "boundary = \"\"")),
            "hemicylinder.toml: key 'contact.boundary' must not be empty");
}

TEST(SceneReaderErrors, SceneNameWithAPathSeparatorIsRejected) {
  EXPECT_THAT(errorOf(seedWith("name = \"hemicylinder\"", "name = \"a/b\"")),
              StartsWith("hemicylinder.toml: key 'name' = \"a/b\" must be a plain file name"));
}

TEST(SceneReaderErrors, MalformedTomlGivesOneLineMessageWithLineAndColumn) {
  const std::string message = errorOf(seedWith("poisson = 0.3", "poisson = = 0.3"));
  EXPECT_THAT(message, StartsWith("hemicylinder.toml:10:"));
  EXPECT_THAT(message, HasSubstr("TOML syntax error: "));
  const std::string unclosed = errorOf(seedWith("point = [0.0, -1.01]", "point = [0.0, -1.01"));
  EXPECT_THAT(unclosed, StartsWith("hemicylinder.toml:1"));
}

// Found by fuzzing (tests/fuzz/fuzz_scene.cpp): toml++ 3.3.0 breaks an assumption of its parser on
// such a header (an abort, or undefined behaviour); the reader refuses it first
// (src/scene/detail/table_header_guard.hpp).
TEST(SceneReaderErrors, TableNameThatCannotStartAKeyIsASyntaxErrorWithLineAndColumn) {
  EXPECT_EQ(errorOf(seedWith("[material]", "[.material]")),
            "hemicylinder.toml:8:2: TOML syntax error: a table name cannot start with '.' "
            "(expected a bare or quoted key)");
  EXPECT_THAT(errorOf(seedWith("[material]", "[[ +material]]")),
              StartsWith("hemicylinder.toml:8:4: TOML syntax error: a table name cannot start with '+'"));
  for (const std::string header : {"[=]", "[[=", "[[[1]]]", "[ #", "[\t"}) {
    EXPECT_THAT(errorOf(kSeed + header + "\n"), HasSubstr("a table name cannot start with")) << header;
  }
  EXPECT_THAT(errorOf(kSeed + "[\n"), HasSubstr("cannot start with the end of the line"));
}

TEST(SceneReader, BracketLinesInsideMultiLineValuesAreNotTableHeaders) {
  // In a multi-line array, "[+1.0]" is a nested array (which the reader then refuses as one)...
  EXPECT_THAT(errorOf(seedWith("point = [0.0, -1.01]", "point = [\n[+1.0], -1.01]")),
              HasSubstr("key 'obstacle.point[0]' must be a number, got an array"));
  // ... and in a multi-line string, "[.x" is text.
  const Scene scene = parseScene(seedWith("name = \"hemicylinder\"", "name = \"\"\"\n[.x\"\"\""), kSource);
  EXPECT_EQ(scene.name, "[.x");
}

// Found by fuzzing: toml++ 3.3.0 reaches undefined behaviour when it asks whether some non-ASCII
// characters are whitespace; the reader refuses them first (src/scene/detail/non_ascii_guard.hpp).
TEST(SceneReaderErrors, NonAsciiOutsideStringsAndCommentsIsASyntaxErrorWithLineAndColumn) {
  EXPECT_EQ(errorOf(seedWith("young = 3000.0", "young = 3000.0 \u00b0")),
            "hemicylinder.toml:9:16: TOML syntax error: a non-ASCII character is allowed only in a "
            "string or a comment");
  EXPECT_THAT(errorOf(seedWith("young", "young\u00b5")), HasSubstr(":9:6: TOML syntax error: a non-ASCII"));
  EXPECT_THAT(errorOf(kSeed + "[\u00a0a]\n"), HasSubstr(":33:2: TOML syntax error: a non-ASCII"));
  EXPECT_THAT(errorOf(seedWith("name = \"hemicylinder\"", "name = \"hemi\\\u00b0\"")),
              HasSubstr("a backslash must not escape a non-ASCII character"));
  EXPECT_THAT(errorOf(seedWith("name = \"hemicylinder\"", "name = \"\"\"hemi\\\n  \u00a7\"\"\"")),
              HasSubstr(":2:3: TOML syntax error: a line continued with a backslash"));
}

// Found by fuzzing (CI): the scan sees a string after "5.", toml++ a number whose end it
// looks for, asking of 'é' whether it is whitespace. The all-ASCII stand-in is parsed first.
TEST(SceneReaderErrors, NonAsciiInALineThatDoesNotParseNeverReachesTheParser) {
  const std::string finding = "nae = 5.\\\"\u00e9\\\nt\nt = ";
  const std::string message = errorOf(finding);
  EXPECT_THAT(message, StartsWith("hemicylinder.toml:1:"));
  EXPECT_THAT(message, HasSubstr("TOML syntax error: "));
  EXPECT_THAT(message, EndsWith("(each byte of a non-ASCII character read as '~')"));
  // The same error in a valid-looking seed: a bad number before a quoted non-ASCII text.
  EXPECT_THAT(errorOf(seedWith("young = 3000.0", "young = 3000.\\\"\u00b0\"")), HasSubstr(":9:"));
}

// Found by fuzzing: toml++ 3.3.0 assumes a value, never '}', where an array expects one
// (src/scene/detail/array_value_guard.hpp); the reader refuses it first.
TEST(SceneReaderErrors, BraceWhereAnArrayExpectsAValueIsASyntaxErrorWithLineAndColumn) {
  const std::string times = "times  = [0.0, 0.2, 1.0]";
  EXPECT_EQ(errorOf(seedWith(times, "times  = [0.0, 0.2, }")),
            "hemicylinder.toml:23:21: TOML syntax error: expected a value or ']' in the array, saw '}'");
  for (const std::string bad : {"times  = [}", "times  = [\n# a comment\n }", "times = [[0.0, }]]",
                                "times = [{a = [0.0,\n}]}]"})
    EXPECT_THAT(errorOf(seedWith(times, bad)), HasSubstr("expected a value or ']' in the array, saw '}'")) << bad;
  // Before any table header that follows: the header guard parses the text up to each header.
  EXPECT_EQ(errorOf(seedWith("normal = [0.0, 1.0]", "normal = [0.0, 1.0,}")),
            "hemicylinder.toml:14:20: TOML syntax error: expected a value or ']' in the array, saw '}'");
}

TEST(SceneReader, BracesInStringsAndCommentsOfArraysAreText) {
  std::string text = seedWith("times  = [0.0, 0.2, 1.0]", "times  = [0.0, # [}\n 0.2, 1.0] # ,}");
  text.replace(0, 21, "name = '''[}''' # \u00e9");
  text.insert(0, "\xEF\xBB\xBF");  // a byte order mark
  const Scene scene = parseScene(text, kSource);
  EXPECT_EQ(scene.name, "[}");
  ASSERT_EQ(scene.dirichlet.size(), 2U);
  EXPECT_EQ(scene.dirichlet[0].history.times, (std::vector<double>{0.0, 0.2, 1.0}));
}

// Found by fuzzing: a --set value is TOML too, and goes through the same guards; what
// they refuse is read as a string, so the key's type check names it.
TEST(SceneReaderErrors, OverrideValuesMeetTheParserBehindItsGuards) {
  EXPECT_THAT(errorOf(kSeed, {"dirichlet[0].values=[\u03a9"}),
              AllOf(HasSubstr("dirichlet[0].values"), HasSubstr("--set dirichlet[0].values=[\u03a9")));
  EXPECT_THAT(errorOf(kSeed, {"dirichlet[0].times=[0.0, }"}), HasSubstr("dirichlet[0].times"));
}

TEST(SceneReader, NonAsciiInStringsAndCommentsIsRead) {
  // An escaped quote and a continued line in a multi-line string, a literal string, comments.
  std::string text = seedWith("boundary = \"arc\"", "boundary = '\u0393_c' # '\u00b5'");
  const std::string name = "name = \"hemicylinder\"";
  text.replace(text.find(name), name.size(),
               "name = \"\"\"h\\\"\u00e9\\\n  ok \u00b0\"\"\"  # \u00bd \"\u00b5");
  const Scene scene = parseScene(text, kSource);
  EXPECT_EQ(scene.name, "h\"\u00e9ok \u00b0");
  EXPECT_EQ(scene.contact.boundary, "\u0393_c");
}

}  // namespace
}  // namespace stc
