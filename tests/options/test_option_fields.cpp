// Every option is declared, defaulted and range-checked in one place, its struct's fields()
// (src/options/option_fields.hpp): the scene reader and validate() walk the same list. These tests
// walk it too, over every key of [solver]: a value just outside a field's range is refused by both,
// with the key and the same rule, and an in-range value is read into every strategy that has it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/options/solver_spec.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace {

using ::testing::HasSubstr;

// The seed scene (docs/interface.md) without its [solver] table.
const std::string kSeed = R"(name = "hemicylinder"
[mesh]
generator = "half_disc"
arc_nodes = 11
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
steps = 5
[[dirichlet]]
boundary = "top"
component = "y"
times  = [0.0, 1.0]
values = [0.0, -0.11]
)";

/// A numeric field of the scene: its key, a value just outside its range (when the range has a
/// finite lower bound), and the rule.
struct NumericKey {
  std::string key;
  bool integer = false;
  double below = 0.0;
  std::string rule;
};

/// Collects the numeric scene keys with a finite lower bound, each once.
struct NumericKeys {
  std::vector<NumericKey> keys;
  std::set<std::string> seen;

  void add(const char* key, bool integer, const stc::Range& range, stc::Exposure exposure) {
    if (exposure != stc::Exposure::SceneKey || !std::isfinite(range.low) || !seen.insert(key).second) return;
    // Below the range, and not the value that turns the option off.
    double below = range.low_strict ? range.low : range.low - 1.0;
    if (range.off && below == *range.off) below = *range.off - 1.0;
    keys.push_back({key, integer, below, range.rule});
  }
  void operator()(const char* key, const int&, const stc::Range& r, stc::Exposure e = stc::Exposure::SceneKey) {
    add(key, true, r, e);
  }
  void operator()(const char* key, const double&, const stc::Range& r, stc::Exposure e = stc::Exposure::SceneKey) {
    add(key, false, r, e);
  }
  void operator()(const char* key, const std::optional<double>&, const stc::Range& r,
                  stc::Exposure e = stc::Exposure::SceneKey) {
    add(key, false, r, e);
  }
  void operator()(const char* key, const std::optional<int>&, const stc::Range& r,
                  stc::Exposure e = stc::Exposure::SceneKey) {
    add(key, true, r, e);
  }
  void operator()(const char*, const bool&, const stc::Range&, stc::Exposure = stc::Exposure::SceneKey) {}
  template <class E>
  void operator()(const char*, const E&, stc::Keywords<E>, stc::Exposure = stc::Exposure::SceneKey) {}
};

/// Sets every field named `key` to `value` (a key shared by several strategies sets each of them).
struct SetKey {
  std::string key;
  double value;
  int set = 0;

  template <class T, class Rule>
  void operator()(const char* name, T& field, const Rule&, stc::Exposure e = stc::Exposure::SceneKey) {
    if (name != key || e != stc::Exposure::SceneKey) return;
    if constexpr (std::is_same_v<T, int> || std::is_same_v<T, std::optional<int>>) field = static_cast<int>(value), ++set;
    else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::optional<double>>) field = value, ++set;
  }
};

std::vector<NumericKey> numericSceneKeys() {
  stc::Scene scene;
  NumericKeys keys;
  stc::solverTableFields(scene, keys);
  return keys.keys;
}

std::string printed(const NumericKey& k) {
  return k.integer ? std::to_string(static_cast<long long>(k.below)) : std::to_string(k.below);
}

std::string readerError(const std::string& solver_table) {
  try {
    stc::parseScene(kSeed + "[solver]\n" + solver_table, "seed.toml");
  } catch (const stc::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(OptionFields, EveryNumericSceneKeyWithALowerBoundIsCheckedByTheReaderAndByValidate) {
  const std::vector<NumericKey> keys = numericSceneKeys();
  ASSERT_GE(keys.size(), 20u);  // tolerance … nested_tolerance: every numeric key of [solver]
  for (const NumericKey& k : keys) {
    SCOPED_TRACE(k.key);
    // The reader: "key 'solver.KEY' = VALUE is out of range: RULE".
    EXPECT_THAT(readerError(k.key + " = " + printed(k) + "\n"),
                AllOf(HasSubstr("'solver." + k.key + "'"), HasSubstr("is out of range: " + k.rule)));
    // validate(): "<owner> option KEY = VALUE: RULE", the same rule.
    stc::Scene scene;
    SetKey set{k.key, k.below};
    stc::solverTableFields(scene, set);
    ASSERT_GE(set.set, 1);
    try {
      stc::validateSolverTable(scene);
      ADD_FAILURE() << "validate() accepted " << k.key << " = " << k.below;
    } catch (const stc::InputError& e) {
      EXPECT_THAT(e.what(), AllOf(HasSubstr(" option " + k.key + " = "), HasSubstr(": " + k.rule)));
    }
  }
}

TEST(OptionFields, TheDefaultsAreValidAndEveryKeyIsReadIntoEveryStrategyThatHasIt) {
  EXPECT_NO_THROW(stc::validateSolverTable(stc::Scene{}));
  for (const NumericKey& k : numericSceneKeys()) {
    SCOPED_TRACE(k.key);
    // A value in range (the default, doubled where doubling stays in range, e.g. 2000 iterations).
    stc::Scene defaults;
    double value = 0.0;
    stc::solverTableFields(defaults, [&](const char* name, const auto& field, const auto& range,
                                          stc::Exposure e = stc::Exposure::SceneKey) {
      using T = std::decay_t<decltype(field)>;
      if (name != k.key || e != stc::Exposure::SceneKey) return;
      if constexpr (std::is_same_v<T, int> || std::is_same_v<T, double>) {
        value = range.holds(2.0 * field) ? 2.0 * field : field;
      } else if constexpr (std::is_same_v<T, std::optional<double>> || std::is_same_v<T, std::optional<int>>) {
        value = field.value_or(range.low + 1.0);
      }
    });
    std::ostringstream text;
    text.precision(17);
    text << k.key << " = ";
    if (k.integer) text << static_cast<long long>(value);
    else text << std::scientific << value;  // a float, exact with 17 digits
    text << "\n";
    const stc::Scene read = stc::parseScene(kSeed + "[solver]\n" + text.str(), "seed.toml");
    int fields = 0, equal = 0;
    stc::solverTableFields(read, [&](const char* name, const auto& field, const auto&,
                                      stc::Exposure e = stc::Exposure::SceneKey) {
      using T = std::decay_t<decltype(field)>;
      if (name != k.key || e != stc::Exposure::SceneKey) return;
      ++fields;
      if constexpr (std::is_same_v<T, int>) equal += field == static_cast<int>(value);
      else if constexpr (std::is_same_v<T, double>) equal += field == value;
      else if constexpr (std::is_same_v<T, std::optional<double>>) equal += field && *field == value;
      else if constexpr (std::is_same_v<T, std::optional<int>>) equal += field && *field == static_cast<int>(value);
    });
    EXPECT_GE(fields, 1);
    EXPECT_EQ(equal, fields);
  }
}

TEST(OptionFields, RangesHoldTheirOwnBoundsAndRefuseNaN) {
  EXPECT_TRUE(stc::atLeast(1).holds(1.0));
  EXPECT_FALSE(stc::atLeast(1).holds(0.0));
  EXPECT_FALSE(stc::positive().holds(0.0));
  EXPECT_FALSE(stc::positive().holds(INFINITY));
  EXPECT_TRUE(stc::inUnitHalfOpen().holds(1.0));
  EXPECT_FALSE(stc::inOpenUnit().holds(1.0));
  EXPECT_TRUE(stc::offOrAtLeast(2).holds(0.0));
  EXPECT_FALSE(stc::offOrAtLeast(2).holds(1.0));
  for (const stc::Range& r : {stc::atLeast(0), stc::positive(), stc::inOpenUnit(), stc::inUnitClosed()})
    EXPECT_FALSE(r.holds(NAN)) << r.rule;
}

TEST(OptionFields, AKeyOutsideTheSchemaIsRefusedWithTheKeysAllowed) {
  EXPECT_THAT(readerError("coarse_rank = 3\n"),
              AllOf(HasSubstr("unknown key 'solver.coarse_rank'"), HasSubstr("zone_margin"),
                    HasSubstr("nested_tolerance"), HasSubstr("pgd_gap_share")));
  // Library-only fields are not keys of the scene.
  EXPECT_THAT(readerError("max_skip = 3\n"), HasSubstr("unknown key 'solver.max_skip'"));
}

TEST(OptionFields, EverySolverKeyOfTheCodeIsDocumentedAndNoOther) {
  // docs/scene_format.md lists each key as "| `solver.KEY` | ...".
  std::ifstream page(std::string(STC_SOURCE_DIR) + "/docs/scene_format.md");
  ASSERT_TRUE(page) << "docs/scene_format.md";
  std::set<std::string> documented;
  const std::regex row(R"(^\| `solver\.([a-z_]+)` \|)");
  for (std::string line; std::getline(page, line);)
    if (std::smatch m; std::regex_search(line, m, row)) documented.insert(m[1]);
  std::set<std::string> code = {"name"};
  stc::Scene scene;
  stc::solverTableFields(scene, [&](const char* key, const auto&, const auto&, stc::Exposure e = stc::Exposure::SceneKey) {
    if (e == stc::Exposure::SceneKey) code.insert(key);
  });
  EXPECT_EQ(documented, code);
}

// ReducedInterfaceOptions::searchScaleOn: (n_Z / 40)^γ on a 2D zone of more than 40 nodes, else 1;
// 1 in 3D and with γ = 0.
TEST(ReducedInterface, TheSearchDirectionGrowsWithA2dZoneOfMoreThan40Nodes) {
  stc::fas::ReducedInterfaceOptions o;
  EXPECT_DOUBLE_EQ(o.searchScaleOn(40, 2), 1.0);
  EXPECT_DOUBLE_EQ(o.searchScaleOn(29, 2), 1.0);
  EXPECT_NEAR(o.searchScaleOn(160, 2), std::sqrt(2.0), 1e-15);  // 4^¼
  EXPECT_DOUBLE_EQ(o.searchScaleOn(160, 3), 1.0);
  o.search_growth = 0.0;
  EXPECT_DOUBLE_EQ(o.searchScaleOn(160, 2), 1.0);
  o.search_growth = -0.1;
  EXPECT_THROW(o.validate(), stc::InputError);
}
