// The 3D build of the Gmsh reader (src/mesh/gmsh_reader.hpp): tetrahedra and named boundary surfaces.
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>

#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/detail/gmsh_sections.hpp"
#include "stcontact/mesh/facet_measure.hpp"
#include "stcontact/mesh/gmsh_reader.hpp"

namespace stc {
namespace {

using detail::GmshData;
using detail::RawTriangle;

std::string at(const std::string& source, int line) { return source + ": line " + std::to_string(line) + ": "; }

// Keeps the nodes that tetrahedra use (renumbered in file order); `index` maps file order to them.
void buildNodesAndTets(const GmshData& data, std::vector<int>& index, TetMesh& mesh) {
  int used = 0;
  index = detail::usedNodeIndex(data.coords.size(), data.tets, used);
  mesh.nodes.resize(3, used);
  mesh.node_tags.resize(static_cast<std::size_t>(used));
  for (std::size_t i = 0; i < index.size(); ++i)
    if (index[i] >= 0) {
      mesh.nodes.col(index[i]) = data.coords[i];
      mesh.node_tags[static_cast<std::size_t>(index[i])] = data.node_tags[i];
    }
  mesh.tets.resize(4, static_cast<Eigen::Index>(data.tets.size()));
  for (std::size_t e = 0; e < data.tets.size(); ++e)
    for (int a = 0; a < 4; ++a) mesh.tets(a, static_cast<Eigen::Index>(e)) = index[data.tets[e][a]];
}

// Gmsh does not promise an orientation of tetrahedra: a negative one gets two nodes swapped; a
// flat one (|volume| ≤ 1e-12 of the mean, as TetMesh::validate) is named by element tag and line.
void orientTets(const GmshData& data, const std::string& source, TetMesh& mesh) {
  double mean = 0.0;
  for (int e = 0; e < mesh.numElements(); ++e) mean += std::abs(mesh.sixSignedVolume(e));
  mean /= std::max(1, mesh.numElements());
  for (int e = 0; e < mesh.numElements(); ++e) {
    const double volume6 = mesh.sixSignedVolume(e);
    if (!(std::abs(volume6) > 1e-12 * mean)) {
      const auto [tag, line] = data.tet_origin[static_cast<std::size_t>(e)];
      throw InputError(at(source, line) + "tetrahedron " + std::to_string(tag) + " is degenerate (zero volume)");
    }
    if (volume6 < 0.0) std::swap(mesh.tets(2, e), mesh.tets(3, e));
  }
}

// `face` rotated so that its smallest node id comes first: the same cyclic order, so the same side.
std::array<int, 3> rotatedToSmallest(std::array<int, 3> face) {
  std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
  return face;
}

// Conforming tetrahedra (all positive once orientTets has run): an outward face, with its cyclic
// order, belongs to one tetrahedron at most, since an interior face is shared by two tetrahedra
// that see it with opposite orders, one on each side. A second tetrahedron with the same oriented
// face lies on the same side as the first: the two repeat or overlap each other, which would count
// the material twice. Named by both Gmsh tags.
void checkConforming(const GmshData& data, const std::string& source, const TetMesh& mesh) {
  std::map<std::array<int, 3>, int> owner;  // oriented face (smallest id first) → tetrahedron
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int f = 0; f < 4; ++f) {
      const auto [it, first] = owner.emplace(rotatedToSmallest(outwardFace(mesh, e, f)), e);
      if (first) continue;
      const auto [tag, line] = data.tet_origin[static_cast<std::size_t>(e)];
      const long long other = data.tet_origin[static_cast<std::size_t>(it->second)].first;
      const bool same = std::is_permutation(&mesh.tets(0, e), &mesh.tets(0, e) + 4, &mesh.tets(0, it->second));
      throw InputError(at(source, line) + "tetrahedron " + std::to_string(tag) +
                       (same ? " repeats tetrahedron " + std::to_string(other) + " (the same four nodes)"
                             : " overlaps tetrahedron " + std::to_string(other) +
                                   " (both lie on the same side of a face they share)"));
    }
}

// Every triangle of a surface with physical groups joins each group, oriented as the boundary
// face of the body it is (outward); a triangle that is not a boundary face, or that a group already
// holds (its area would count twice), is an InputError.
void buildSurfaceGroups(const GmshData& data, const std::vector<int>& index, const std::string& source,
                        TetMesh& mesh) {
  std::map<std::array<int, 3>, std::array<int, 3>> outward;  // sorted node ids → oriented face
  std::map<std::string, std::set<std::array<int, 3>>> seen;   // per group, its faces so far
  for (const auto& face : boundaryTriangles(mesh)) {
    std::array<int, 3> key = face;
    std::sort(key.begin(), key.end());
    outward.emplace(key, face);
  }
  for (const auto& [surface, triangles] : data.surface_triangles) {
    const auto groups = data.surface_groups.find(surface);
    if (groups == data.surface_groups.end())
      throw InputError(at(source, triangles.front().line) + "triangles on surface " + std::to_string(surface) +
                       ", which $Entities does not list");
    for (long long physical : groups->second) {
      const auto named = data.names.find({2, physical});
      const std::string name = named == data.names.end() ? std::to_string(physical) : named->second;
      for (const RawTriangle& t : triangles) {
        std::array<int, 3> key{};
        for (int a = 0; a < 3; ++a) key[a] = index[t.nodes[a]];
        std::sort(key.begin(), key.end());
        const auto face = outward.find(key);
        if (key[0] < 0 || face == outward.end())
          throw InputError(at(source, t.line) + "triangle " + std::to_string(t.tag) + " of boundary '" + name +
                           "' is not a boundary face of the tetrahedra");
        if (!seen[name].insert(key).second)
          throw InputError(at(source, t.line) + "triangle " + std::to_string(t.tag) + " of boundary '" + name +
                           "' repeats a face already in it");
        mesh.groups[name].triangles.push_back(face->second);
      }
    }
  }
}

// The triangles, renumbered over the nodes they use (in file order).
SurfaceTriangles usedNodesAndTriangles(const GmshData& data, const std::vector<RawTriangle>& raw) {
  std::vector<std::array<int, 3>> triangles;
  for (const RawTriangle& t : raw) triangles.push_back(t.nodes);
  int used = 0;
  const std::vector<int> index = detail::usedNodeIndex(data.coords.size(), triangles, used);
  SurfaceTriangles surface;
  surface.nodes.resize(3, used);
  for (std::size_t i = 0; i < index.size(); ++i)
    if (index[i] >= 0) surface.nodes.col(index[i]) = data.coords[i];
  surface.triangles.resize(3, static_cast<Eigen::Index>(raw.size()));
  for (std::size_t e = 0; e < triangles.size(); ++e)
    for (int a = 0; a < 3; ++a) surface.triangles(a, static_cast<Eigen::Index>(e)) = index[static_cast<std::size_t>(triangles[e][a])];
  return surface;
}

// A triangle of area ≤ 1e-12 of the mean is named by element tag and line.
void requireNonDegenerate(const SurfaceTriangles& surface, const std::vector<RawTriangle>& raw, const std::string& source) {
  const Eigen::MatrixXd x = surface.nodes;
  const auto area = [&](Eigen::Index e) {
    return facetMeasure(x, {surface.triangles(0, e), surface.triangles(1, e), surface.triangles(2, e)});
  };
  double mean = 0.0;
  for (Eigen::Index e = 0; e < surface.triangles.cols(); ++e) mean += area(e) / static_cast<double>(raw.size());
  for (Eigen::Index e = 0; e < surface.triangles.cols(); ++e)
    if (!(area(e) > 1e-12 * mean))
      throw InputError(at(source, raw[static_cast<std::size_t>(e)].line) + "triangle " +
                       std::to_string(raw[static_cast<std::size_t>(e)].tag) + " is degenerate (zero area)");
}

}  // namespace

TetMesh parseGmsh3d(std::istream& in, const std::string& source_name) {
  const GmshData data = detail::readSections(in, source_name, 3);
  TetMesh mesh;
  std::vector<int> index;
  buildNodesAndTets(data, index, mesh);
  orientTets(data, source_name, mesh);
  checkConforming(data, source_name, mesh);
  buildSurfaceGroups(data, index, source_name, mesh);
  detail::finishMesh(mesh, source_name);
  return mesh;
}

TetMesh readGmsh3d(const std::filesystem::path& file) {
  std::ifstream in = detail::openMeshFile(file);
  return parseGmsh3d(in, file.string());
}

SurfaceTriangles parseGmshSurface(std::istream& in, const std::string& source_name) {
  const GmshData data = detail::readSections(in, source_name, 3, false);
  if (!data.tets.empty())
    throw InputError(at(source_name, data.tet_origin.front().second) + "tetrahedron " +
                     std::to_string(data.tet_origin.front().first) + ": a rigid surface is given by its triangles alone "
                     "(this file holds a volume mesh)");
  std::vector<RawTriangle> raw;
  for (const auto& [surface, triangles] : data.surface_triangles) raw.insert(raw.end(), triangles.begin(), triangles.end());
  if (raw.empty())
    throw InputError(source_name + ": no triangles (with Mesh.SaveAll = 0, Gmsh saves only the elements of physical "
                                   "groups: is there a Physical Surface?)");
  std::sort(raw.begin(), raw.end(), [](const RawTriangle& a, const RawTriangle& b) { return a.line < b.line; });
  SurfaceTriangles surface = usedNodesAndTriangles(data, raw);
  requireNonDegenerate(surface, raw, source_name);
  return surface;
}

SurfaceTriangles readGmshSurface(const std::filesystem::path& file) {
  std::ifstream in = detail::openMeshFile(file);
  return parseGmshSurface(in, file.string());
}

}  // namespace stc
