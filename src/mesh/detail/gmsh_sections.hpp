#pragma once
// What the Gmsh MSH 4.1 reader (src/mesh/gmsh_reader.hpp) reads from a file before it builds a mesh:
// shared by the 2D build (gmsh_reader.cpp) and the 3D one (gmsh_reader_3d.cpp). Internal.
#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <fstream>
#include <istream>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "stcontact/core/input_error.hpp"

namespace stc::detail {

/// A 2-node line element as read: node positions in file order, and where it was.
struct RawEdge {
  std::array<int, 2> nodes;
  long long tag;
  int line;
};

/// A 3-node triangle on a surface entity (3D meshes: a boundary face), as read.
struct RawTriangle {
  std::array<int, 3> nodes;
  long long tag;
  int line;
};

/// Everything read from the file, before unused nodes are dropped. `dimension` (2 or 3) is what
/// the caller reads: it decides which elements are the body and which the named boundaries.
struct GmshData {
  int dimension = 2;
  std::map<std::pair<long long, long long>, std::string> names;  ///< (dim, tag) -> name
  std::map<long long, std::vector<long long>> curve_groups;      ///< curve -> physical tags
  std::map<long long, std::vector<long long>> surface_groups;    ///< surface -> physical tags
  std::unordered_map<long long, int> node_index;                 ///< node tag -> file order
  std::vector<long long> node_tags;
  std::vector<Eigen::Vector3d> coords;
  std::vector<std::array<int, 3>> triangles;               ///< 2D: the body
  std::vector<std::pair<long long, int>> triangle_origin;  ///< (element tag, line) per triangle
  std::map<long long, std::vector<RawEdge>> curve_edges;  ///< curve -> its line elements (2D)
  std::vector<std::array<int, 4>> tets;                    ///< 3D: the body
  std::vector<std::pair<long long, int>> tet_origin;       ///< (element tag, line) per tetrahedron
  std::map<long long, std::vector<RawTriangle>> surface_triangles;  ///< surface -> its triangles (3D)
};

/// Reads every section of an MSH 4.1 ASCII file for a reader of `dimension` (2 or 3): nodes (z must
/// be 0 in 2D), the body's elements (triangles in 2D, tetrahedra in 3D) and the boundary elements
/// (lines on curves in 2D, triangles on surfaces in 3D). Throws InputError naming file and line.
/// A file without the body's elements is an error unless `body_required` is false (a rigid surface
/// in 3D: its triangles alone).
GmshData readSections(std::istream& in, const std::string& source_name, int dimension, bool body_required = true);

/// The index of each node read (file order) among the nodes `elements` use (each element a range of
/// node positions in file order), renumbered in file order; −1 for a node no element uses. `used`
/// is their count. The readers keep only those nodes (an unused one would add a zero row).
template <class Elements>
std::vector<int> usedNodeIndex(std::size_t num_nodes, const Elements& elements, int& used) {
  std::vector<int> index(num_nodes, -1);
  for (const auto& element : elements)
    for (int node : element) index[static_cast<std::size_t>(node)] = 0;
  used = 0;
  for (int& i : index)
    if (i == 0) i = used++;
  return index;
}

/// Finalises the groups of a built mesh (TriMesh or TetMesh) and validates it, prefixing any
/// InputError with the file name.
template <class MeshT>
void finishMesh(MeshT& mesh, const std::string& source_name) {
  mesh.finalizeGroups();
  try {
    mesh.validate();
  } catch (const InputError& e) {
    throw InputError(source_name + ": " + e.what());
  }
}

/// Opens `file` for reading; InputError "cannot open mesh file 'X'" if it cannot (a folder included:
/// an ifstream "opens" a directory, then reads nothing), a MissingFileError when nothing is there.
std::ifstream openMeshFile(const std::filesystem::path& file);

}  // namespace stc::detail
