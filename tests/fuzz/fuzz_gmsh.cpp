// libFuzzer target: Gmsh MSH 4.1 text -> Mesh (src/mesh/gmsh_reader.hpp). InputError is the
// expected answer to bad input; any other exception, a crash, a sanitizer report, a leak, or a
// returned mesh that breaks the reader's promises is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "src/core/input_error.hpp"
#include "src/mesh/gmsh_reader.hpp"

namespace {

void require(bool ok, const char* promise) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_gmsh: the reader returned a mesh that breaks: %s\n", promise);
  std::abort();
}

bool isNode(const stc::Mesh& mesh, int id) { return id >= 0 && id < mesh.numNodes(); }

/// The promises of gmsh_reader.hpp that assembly relies on: node ids in range, every triangle
/// counter-clockwise, every kept node used by a triangle, group nodes sorted and on their edges.
void checkMesh(const stc::Mesh& mesh) {
  require(mesh.numElements() > 0, "at least one triangle");
  std::vector<bool> used(static_cast<std::size_t>(mesh.numNodes()), false);
  for (int e = 0; e < mesh.numElements(); ++e) {
    for (int a = 0; a < 3; ++a) {
      require(isNode(mesh, mesh.triangles(a, e)), "triangle node ids in range");
      used[static_cast<std::size_t>(mesh.triangles(a, e))] = true;
    }
    require(mesh.twiceSignedArea(e) > 0.0, "triangles counter-clockwise");
  }
  for (bool u : used) require(u, "every node is used by a triangle");
  for (const auto& [name, group] : mesh.groups) {
    require(!group.edges.empty(), "a group has edges");
    for (const auto& edge : group.edges)
      require(isNode(mesh, edge[0]) && isNode(mesh, edge[1]), "edge node ids in range");
    for (std::size_t i = 1; i < group.nodes.size(); ++i)
      require(group.nodes[i - 1] < group.nodes[i], "group nodes sorted and unique");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    checkMesh(stc::parseGmsh(in, "fuzz.msh"));
  } catch (const stc::InputError&) {
    // The expected answer to bad input; anything else propagates and is reported as a crash.
  }
  return 0;
}
