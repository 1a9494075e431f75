#pragma once
// P1 triangle mesh with named boundary groups (node sets and their boundary edges).
#include <Eigen/Core>
#include <array>
#include <map>
#include <string>
#include <vector>

namespace stc {

/// A named part of the boundary: its edges (pairs of node ids) and the nodes they touch,
/// sorted and unique. Built-in generators and the Gmsh reader fill both.
struct BoundaryGroup {
  std::vector<int> nodes;
  std::vector<std::array<int, 2>> edges;
};

struct TriMesh {
  Eigen::Matrix2Xd nodes;      ///< coordinates, one column per node
  /// The mesh file's tag of each node (Gmsh's node tags, what a user sees in the file and in
  /// contact.csv); empty for a mesh made here (a generator, a mirror image), numbered from 1 then:
  /// nodeTags (body_mesh.hpp).
  std::vector<long long> node_tags;
  Eigen::Matrix3Xi triangles;  ///< node ids, one column per element, counter-clockwise
  std::map<std::string, BoundaryGroup> groups;

  int numNodes() const { return static_cast<int>(nodes.cols()); }
  int numDofs() const { return 2 * numNodes(); }
  int numElements() const { return static_cast<int>(triangles.cols()); }

  /// Twice the signed area of element e (positive when counter-clockwise).
  double twiceSignedArea(int e) const;
  /// The group named `name`; throws InputError listing the groups the mesh has.
  const BoundaryGroup& group(const std::string& name) const;
  /// Throws InputError naming the first element that is inverted or degenerate
  /// (|area| below 1e-12 of the mean element area), or a node id out of range.
  void validate() const;
  /// Fills `nodes` of every group from its edges (sorted, unique).
  void finalizeGroups();
};

/// The element node ids, one column per element (the twin of elementNodes(TetMesh), tet_mesh.hpp),
/// for code written once for both meshes.
inline const Eigen::Matrix3Xi& elementNodes(const TriMesh& mesh) { return mesh.triangles; }
inline Eigen::Matrix3Xi& elementNodes(TriMesh& mesh) { return mesh.triangles; }

/// The edges that belong to exactly one triangle, each oriented as its (counter-clockwise) triangle
/// runs it: the body lies on its left, its outward normal is (t_y, −t_x) for t = x_b − x_a. The 2D
/// twin of boundaryTriangles (tet_mesh.hpp).
std::vector<std::array<int, 2>> boundaryEdges(const TriMesh& mesh);

}  // namespace stc
