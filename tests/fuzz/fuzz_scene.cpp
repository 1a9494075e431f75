// libFuzzer target: scene text (TOML) -> Scene, through the reader and all its checks
// (src/scene/scene_reader.hpp), then the size estimate and, for a generator mesh small enough
// (estimated at most kGeneratorNodes nodes), the generator with the scene's parameters
// (src/problem/size_estimate.hpp, src/mesh/: a parameter of 2³¹ − 1 overflowed a generator).
// Leading lines "#set KEY=VALUE" (TOML comments, so the text stays the same scene) are also applied
// as `--set` overrides, so the override parser is fuzzed too.
// InputError is the expected answer to bad input; any other exception, a crash, a sanitizer
// report, a leak, or a returned scene that breaks the reader's promises is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/problem/size_estimate.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace {

/// The "#set " lines at the top of the text, without the prefix.
std::vector<std::string> leadingOverrides(std::string_view text) {
  constexpr std::string_view kPrefix = "#set ";
  std::vector<std::string> overrides;
  while (text.substr(0, kPrefix.size()) == kPrefix) {
    const std::size_t end = text.find('\n');
    overrides.emplace_back(text.substr(kPrefix.size(), end - kPrefix.size()));  // npos: to the end
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
  }
  return overrides;
}

void require(bool ok, const char* promise) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_scene: the reader returned a scene that breaks: %s\n", promise);
  std::abort();
}

/// A few promises of scene_reader.hpp / scene.hpp that later stages rely on without checking.
void checkScene(const stc::Scene& scene) {
  require(!scene.name.empty(), "name is nonempty");
  require(scene.mesh.generator.empty() != scene.mesh.file.empty(), "one of generator and file");
  require(std::abs(scene.obstacle.normal.norm() - 1.0) < 1e-12, "obstacle.normal is a unit vector");
  require(scene.time.steps >= 2 && scene.time.end > 0.0, "time.steps >= 2, time.end > 0");
  auto checkHistory = [](const stc::History& h) {
    require(!h.times.empty() && h.times.size() == h.values.size(), "times and values match");
    for (std::size_t i = 1; i < h.times.size(); ++i)
      require(h.times[i] > h.times[i - 1], "times strictly increase");
  };
  for (const auto& d : scene.dirichlet) checkHistory(d.history);
  for (const auto& l : scene.loads) checkHistory(l.history);
}

/// Generators at most this large run on every input (a few milliseconds).
constexpr double kGeneratorNodes = 1000.0;

/// The size estimate of every scene, and the generator of the small ones: InputError or a mesh.
void generateMesh(const stc::Scene& scene) {
  const stc::SizeEstimate size = stc::estimateSize(scene);
  require(size.nodes >= 0.0 && size.bytes >= 0.0, "the size estimate is not negative");
  if (scene.mesh.generator.empty() || size.nodes > kGeneratorNodes) return;
  const stc::BodyMesh body = stc::buildBodyMesh(scene.mesh, scene.dimension);
  require(stc::numNodes(body) <= size.nodes, "the generator makes at most the nodes estimated");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const stc::Scene scene = stc::parseScene(text, "fuzz.toml", leadingOverrides(text));
    checkScene(scene);
    generateMesh(scene);
  } catch (const stc::InputError&) {
    // The expected answer to bad input; anything else propagates and is reported as a crash.
  }
  return 0;
}
