// libFuzzer target: Gmsh MSH 4.1 text -> TriMesh and TetMesh (src/mesh/gmsh_reader.hpp), both readers
// on every input. InputError is the
// expected answer to bad input; any other exception, a crash, a sanitizer report, a leak, or a
// returned mesh that breaks the reader's promises is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/gmsh_reader.hpp"

namespace {

void require(bool ok, const char* promise) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_gmsh: the reader returned a mesh that breaks: %s\n", promise);
  std::abort();
}

bool isNode(const stc::TriMesh& mesh, int id) { return id >= 0 && id < mesh.numNodes(); }

/// The promises of gmsh_reader.hpp that assembly relies on: node ids in range, every triangle
/// counter-clockwise, every kept node used by a triangle, group nodes sorted and on their edges.
void checkMesh(const stc::TriMesh& mesh) {
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

/// The 3D reader's promises: tetrahedra of positive volume on nodes in range, every node used,
/// group triangles on nodes in range.
void checkSolid(const stc::TetMesh& mesh) {
  require(mesh.numElements() > 0, "at least one tetrahedron");
  std::vector<bool> used(static_cast<std::size_t>(mesh.numNodes()), false);
  for (int e = 0; e < mesh.numElements(); ++e) {
    for (int a = 0; a < 4; ++a) {
      const int id = mesh.tets(a, e);
      require(id >= 0 && id < mesh.numNodes(), "tetrahedron node ids in range");
      used[static_cast<std::size_t>(id)] = true;
    }
    require(mesh.sixSignedVolume(e) > 0.0, "tetrahedra of positive volume");
  }
  for (bool u : used) require(u, "every node is used by a tetrahedron");
  for (const auto& [name, group] : mesh.groups)
    for (const auto& t : group.triangles)
      for (int id : t) require(id >= 0 && id < mesh.numNodes(), "group triangle node ids in range");
}

// A rigid surface: triangles over nodes in range, every node used, no triangle of zero area.
void checkSurface(const stc::SurfaceTriangles& surface) {
  require(surface.triangles.cols() > 0, "a surface has triangles");
  std::vector<bool> used(static_cast<std::size_t>(surface.nodes.cols()), false);
  for (Eigen::Index e = 0; e < surface.triangles.cols(); ++e)
    for (int a = 0; a < 3; ++a) {
      const int id = surface.triangles(a, e);
      require(id >= 0 && id < surface.nodes.cols(), "surface triangle node ids in range");
      used[static_cast<std::size_t>(id)] = true;
    }
  for (bool u : used) require(u, "every node is used by a triangle");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    std::istringstream in(text);
    checkMesh(stc::parseGmsh(in, "fuzz.msh"));
  } catch (const stc::InputError&) {
    // The expected answer to bad input; anything else propagates and is reported as a crash.
  }
  try {
    std::istringstream in(text);
    checkSolid(stc::parseGmsh3d(in, "fuzz.msh"));
  } catch (const stc::InputError& e) {
    // The surface reader reads the sections as the 3D one does and departs from it only where a file
    // has no tetrahedra (any other input meets the same refusal, or the surface reader's "volume
    // mesh"): only those inputs are parsed again, which keeps the target at two parses an input.
    if (std::string(e.what()).find("no tetrahedra") != std::string::npos) {
      try {
        std::istringstream again(text);
        checkSurface(stc::parseGmshSurface(again, "fuzz.msh"));
      } catch (const stc::InputError&) {
      }
    }
  }
  return 0;
}
