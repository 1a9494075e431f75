// The stopping rule at the ends of every range (docs/method.md §2, "Stopping"; docs/reliability.md):
// every numeric and keyword key of the [solver] table an iterative strategy reads, and every
// material key, at the ends of the range its fields() list (or the scene reader) documents and ten
// decades inside them, on the seed scene (2D), the hemisphere (3D) and two cylinders (two bodies),
// at small settings. A run that reports converged must have its true error, against the incremental
// solution of the same problem, at most the tolerance; a refusal (InputError) or any other ending
// (the iteration cap, stagnation, a numerical issue) is an honest answer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/seed_scene.hpp"
#include "fixtures/two_bodies_scene.hpp"
#include "stcontact/core/input_error.hpp"
#include "strategies/strategy_fixture.hpp"

namespace {

constexpr double kTolerance = 1e-6;
constexpr int kCap = 150;  // iterations: an extreme that converges does so well within it

const char* const kScenes[] = {"seed", "hemisphere", "pair"};

stc::Scene sceneNamed(const std::string& name) {
  stc::Scene scene;
  if (name == "seed") scene = stc::test::seedScene(21, 11);
  if (name == "hemisphere") scene = stc::test::hemisphereScene(3, 11);
  if (name == "pair") scene = stc::test::mirroredPair(stc::test::seedScene(21, 11));
  scene.solver.setTolerance(kTolerance);
  scene.solver.setMaxIterations(kCap);
  return scene;
}

/// One value of one key: a [solver] key set as the scene reader would (in every strategy that has
/// it), or a material key.
struct RangeCase {
  std::string scene, strategy, key;
  double number = 0.0;      ///< numeric keys
  std::string keyword;      ///< keyword and boolean keys ("true"/"false")
};

std::string nameOf(const RangeCase& c) {
  std::string value = c.keyword.empty() ? std::to_string(c.number) : c.keyword;
  if (c.keyword.empty()) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", c.number);  // nextafter's neighbours differ in the last digits
    value = text;
  }
  std::string name = c.scene + "_" + c.strategy + "_" + c.key + "_" + value;
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

void PrintTo(const RangeCase& c, std::ostream* os) { *os << nameOf(c); }

/// The values a range is scanned at: each finite end (its nearest representable value inside when
/// strict) and ten decades inside it; an unbounded end at ten decades above the default (1000 for an
/// integer).
std::vector<double> valuesOf(const stc::Range& r, double default_value, bool integer) {
  std::vector<double> out;
  const auto add = [&](double v) {
    if (integer) v = std::round(v);
    if (r.holds(v) && std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
  };
  const double span = std::isfinite(r.high) ? r.high - r.low : std::max(1.0, std::abs(default_value));
  if (std::isfinite(r.low)) {
    add(r.low_strict ? (r.low == 0.0 ? std::numeric_limits<double>::min() : std::nextafter(r.low, r.high)) : r.low);
    if (!integer) add(r.low + 1e-10 * span);
  }
  if (std::isfinite(r.high)) {
    add(r.high_strict ? std::nextafter(r.high, r.low) : r.high);
    if (!integer) add(r.high - 1e-10 * span);
  } else {
    add(integer ? 1000.0 : (default_value != 0.0 ? 1e10 * default_value : 1e10));
  }
  if (r.off) add(*r.off);
  return out;
}

/// Whether strategy `s`'s options hold the key (the [solver] keys it reads).
template <class Options>
bool holds(const Options& options, const std::string& key) {
  bool found = false;
  Options::fields(options, [&](const char* name, const auto&, const auto&, stc::Exposure e = stc::Exposure::SceneKey) {
    found = found || (e == stc::Exposure::SceneKey && key == name);
  });
  return found;
}

bool readBy(const std::string& strategy, const std::string& key) {
  const stc::SolverSpec spec;
  if (key == "search_scale" || key == "search_law") return true;  // the model's: every strategy
  if (strategy == "latin") return holds(spec.latin, key);
  if (strategy == "latin-pgd") return holds(spec.latin_pgd, key);
  if (strategy == "fas-aposteriori") return holds(spec.fas_aposteriori, key);
  return holds(spec.fas_apriori, key);
}

std::vector<RangeCase> rangeCases() {
  std::vector<RangeCase> cases;
  stc::Scene defaults;
  for (const char* scene : kScenes)
    for (const char* strategy : {"latin", "latin-pgd", "fas-aposteriori", "fas-apriori"}) {
      // A key that several strategies' structs hold (tolerance, pre_relaxations) is visited once each.
      const auto add = [&](const std::string& key, double number, const std::string& keyword) {
        const RangeCase c{scene, strategy, key, number, keyword};
        const bool seen = std::any_of(cases.begin(), cases.end(), [&](const RangeCase& o) { return nameOf(o) == nameOf(c); });
        if (readBy(strategy, key) && !seen) cases.push_back(c);
      };
      stc::solverTableFields(defaults, [&](const char* key, const auto& field, const auto& rule,
                                           stc::Exposure e = stc::Exposure::SceneKey) {
        using T = std::decay_t<decltype(field)>;
        using R = std::decay_t<decltype(rule)>;
        if (e != stc::Exposure::SceneKey || std::string(key) == "max_iterations") return;
        if constexpr (std::is_same_v<T, bool>) {
          add(key, 0.0, "true");
          add(key, 0.0, "false");
        } else if constexpr (std::is_same_v<R, stc::Range>) {
          const bool integer = std::is_same_v<T, int> || std::is_same_v<T, std::optional<int>>;
          double default_value = 0.0;
          if constexpr (std::is_same_v<T, int> || std::is_same_v<T, double>) default_value = field;
          else default_value = field.value_or(rule.low + 1.0);
          for (double v : valuesOf(rule, default_value, integer)) add(key, v, "");
        } else {
          for (const auto& [name, value] : rule) add(key, 0.0, std::string(name));
        }
      });
      // The material's keys, in the ranges the scene reader checks (docs/scene_format.md).
      for (double young : {1e-140, 1e140}) cases.push_back({scene, strategy, "material.young", young, ""});
      for (double nu : {stc::kPoissonLow, stc::kPoissonLow + 1e-10, stc::kPoissonHigh - 1e-10, stc::kPoissonHigh})
        cases.push_back({scene, strategy, "material.poisson", nu, ""});
      for (double mu : {0.0, 1e-10, 1e10}) cases.push_back({scene, strategy, "contact.friction", mu, ""});
    }
  return cases;
}

/// Sets `key` to the case's value in every strategy struct that has it, as the scene reader does.
void setKey(stc::Scene& scene, const RangeCase& c) {
  if (c.key == "material.young") scene.material.young = c.number;
  if (c.key == "material.poisson") scene.material.poisson = c.number;
  if (c.key == "contact.friction") scene.contact.friction = c.number;
  stc::solverTableFields(scene, [&](const char* key, auto& field, const auto& rule,
                                    stc::Exposure e = stc::Exposure::SceneKey) {
    using T = std::decay_t<decltype(field)>;
    using R = std::decay_t<decltype(rule)>;
    if (e != stc::Exposure::SceneKey || c.key != key) return;
    if constexpr (std::is_same_v<T, bool>) field = c.keyword == "true";
    else if constexpr (std::is_same_v<T, int> || std::is_same_v<T, std::optional<int>>) field = static_cast<int>(c.number);
    else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::optional<double>>) field = c.number;
    else if constexpr (!std::is_same_v<R, stc::Range>) {
      for (const auto& [name, value] : rule)
        if (name == c.keyword) field = value;
    }
  });
}

/// The incremental reference of a scene's model (its material included), solved once.
const stc::test::StrategyFixture& reference(const stc::Scene& scene, const std::string& label) {
  static std::map<std::string, std::unique_ptr<stc::test::StrategyFixture>> fixtures;
  auto& f = fixtures[label];
  if (!f) f = std::make_unique<stc::test::StrategyFixture>(scene);
  return *f;
}

class RangeScan : public ::testing::TestWithParam<RangeCase> {};

TEST_P(RangeScan, ConvergedMeansATrueErrorWithinTheTolerance) {
  const RangeCase& c = GetParam();
  stc::Scene scene = sceneNamed(c.scene);
  setKey(scene, c);
  try {
    stc::validateSolverTable(scene);  // the range the reader checks: every value here is inside it
    const bool material = c.key.rfind("material.", 0) == 0 || c.key == "contact.friction";
    const stc::test::StrategyFixture& base =
        reference(material ? scene : sceneNamed(c.scene), material ? nameOf(c) : c.scene);
    if (!base.incremental.summary.converged() || !base.reference.defined()) return;  // no measure to hold it to
    const stc::Problem problem = stc::buildProblem(scene);  // the search direction may differ
    const stc::SolveSummary s = base.solveAgainstReference(c.strategy, problem, scene.solver).summary;
    stc::test::printMeasured(nameOf(c), s);
    if (!s.converged()) return;  // an honest answer
    ASSERT_TRUE(s.error.has_value()) << s.message;
    EXPECT_LE(*s.error, scene.solver.tolerance()) << s.message;  // the case's own when it sets `tolerance`
  } catch (const stc::InputError& e) {
    std::cout << "[ refused ] " << nameOf(c) << ": " << e.what() << "\n";  // an honest answer
  }
}

INSTANTIATE_TEST_SUITE_P(AtTheEnds, RangeScan, ::testing::ValuesIn(rangeCases()),
                         [](const ::testing::TestParamInfo<RangeCase>& info) { return nameOf(info.param); });

}  // namespace
