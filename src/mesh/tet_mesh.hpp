#pragma once
// P1 tetrahedron mesh with named boundary groups (surface triangles and the nodes they touch):
// the three-dimensional counterpart of TriMesh (src/mesh/tri_mesh.hpp).
#include <Eigen/Core>
#include <array>
#include <map>
#include <string>
#include <vector>

namespace stc {

/// A named part of the boundary surface: its triangles (node ids, counter-clockwise seen from
/// outside the body, so that (x1 − x0) × (x2 − x0) is the outward normal) and the nodes they
/// touch, sorted and unique.
struct SurfaceGroup {
  std::vector<int> nodes;
  std::vector<std::array<int, 3>> triangles;
};

struct TetMesh {
  Eigen::Matrix3Xd nodes;  ///< coordinates, one column per node
  /// The mesh file's tag of each node (Gmsh's node tags, what a user sees in the file and in
  /// contact.csv); empty for a mesh made here (a generator, a mirror image), numbered from 1 then:
  /// nodeTags (body_mesh.hpp).
  std::vector<long long> node_tags;
  Eigen::Matrix4Xi tets;   ///< node ids, one column per element, positive signed volume
  std::map<std::string, SurfaceGroup> groups;

  int numNodes() const { return static_cast<int>(nodes.cols()); }
  int numDofs() const { return 3 * numNodes(); }
  int numElements() const { return static_cast<int>(tets.cols()); }

  /// Six times the signed volume of element e: ((x1 − x0) × (x2 − x0)) · (x3 − x0), positive
  /// when x3 lies on the side of the face (x0, x1, x2) its right-hand normal points to.
  double sixSignedVolume(int e) const;
  /// The group named `name`; throws InputError listing the groups the mesh has.
  const SurfaceGroup& group(const std::string& name) const;
  /// Throws InputError naming the first element that is inverted or degenerate
  /// (|volume| below 1e-12 of the mean element volume), or a node id out of range.
  void validate() const;
  /// Fills `nodes` of every group from its triangles (sorted, unique).
  void finalizeGroups();
};

/// The element node ids, one column per element (the twin of elementNodes(TriMesh), tri_mesh.hpp).
inline const Eigen::Matrix4Xi& elementNodes(const TetMesh& mesh) { return mesh.tets; }
inline Eigen::Matrix4Xi& elementNodes(TetMesh& mesh) { return mesh.tets; }

/// The faces of a positive tetrahedron (0, 1, 2, 3), each oriented outward (counter-clockwise seen
/// from outside): local node numbers.
inline constexpr int kTetFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

/// Face `f` (0–3) of element `e`, oriented outward (kTetFaces), as mesh node ids.
std::array<int, 3> outwardFace(const TetMesh& mesh, int e, int f);

/// The faces that belong to exactly one element, each oriented outward (kTetFaces).
std::vector<std::array<int, 3>> boundaryTriangles(const TetMesh& mesh);

}  // namespace stc
