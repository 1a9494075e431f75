#pragma once
// Node-to-node pairing of two deformable bodies with matching interface meshes (docs/two_bodies.md).
// Each node s of the slave boundary is paired with one node m of the master boundary; in the
// initial configuration (small sliding) the pair's normal n points from the master into the slave
// and the relative displacement u_s − u_m takes the place of the displacement of a node facing a
// rigid obstacle: g = g0 + n · (u_s − u_m).
//  - Along a common normal n̄ (contact.normal): m is the master node right below s along n̄
//    (|(I − n̄ n̄ᵀ)(x_s − x_m)| ≤ 1e-6 of the interface's extent), n = n̄, g0 = n̄ · (x_s − x_m).
//    Two bodies whose surfaces curve away from each other (cylinders, spheres) pair this way: the
//    nodes far from the contact face nodes far from their nearest.
//  - Without it: m is the nearest master node, n = (x_s − x_m) / |x_s − x_m| (g0 = |x_s − x_m|), or
//    the master's outward normal when the nodes coincide (g0 = 0): conforming interfaces.
// The master's outward normal n_m at a node is the measure-weighted mean of the outward normals of
// its boundary facets.
//
// The meshes match when the pairs face each other and no master node is paired twice. Two checks
// say so: n · n_m ≥ 1/2 (the pair lies within 60° of the master's normal: a slave node behind the
// master boundary, overlapping bodies, or boundaries that do not face each other fail it; along a
// common normal n̄ · n_m ≥ 0, the master node on the master's side), and
// each master node is paired once.
//
// Node to segment (contact.pairing = "segment", non-matching meshes; along a common normal n̄ only):
// the line through slave node s along n̄ meets the master boundary at a point p of one of its facets
// (an edge in 2D, a triangle in 3D, the nearest such point on the master's side); p = Σ_j w_j x_j over
// the facet's nodes with barycentric weights w_j ≥ 0, Σ w_j = 1, and the relative displacement is
// u_s − Σ_j w_j u_j: g = g0 + n̄ · (u_s − Σ_j w_j u_j), g0 = n̄ · (x_s − p) (small sliding: p stays the
// pair's point). Weights below 1e-12 are dropped, so a slave node right above a master node pairs
// with that node alone, as node to node. The facet must face the slave (n̄ · n_F ≥ 0, n_F its outward
// normal); master nodes may be shared by any number of slave nodes.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "stcontact/mesh/tet_mesh.hpp"
#include "stcontact/mesh/tri_mesh.hpp"

namespace stc {

struct NodePair {
  int master = -1;         ///< mesh node id of the master node (node to segment: of the largest weight)
  Eigen::VectorXd normal;  ///< from the master into the slave, unit
  double gap = 0.0;        ///< g0 ≥ 0
  std::vector<int> facet;  ///< the master nodes compared with the slave: {master}, or the facet's nodes
  std::vector<double> weights;  ///< their weights w_j > 0, Σ w_j = 1 (node to node: {1})
};

/// "node 12 at (x, y)": a node named in an input error.
std::string describeNode(const Eigen::MatrixXd& positions, int node);

/// Outward unit normal of the body at each node of boundary group `group` (its `nodes` order),
/// from the mesh's boundary facets that lie in the group.
Eigen::MatrixXd outwardNodeNormals(const TriMesh& mesh, const std::string& group);
Eigen::MatrixXd outwardNodeNormals(const TetMesh& mesh, const std::string& group);

/// The pair of each node of `slave_nodes` among the master group's nodes `master_nodes` whose
/// outward normals are `master_normals` (d × master_nodes.size()), along the unit `common_normal`
/// when it is not empty. Throws InputError naming the node when a slave node has no master node
/// along the common normal, a pair does not face the master boundary or a master node is paired
/// twice.
std::vector<NodePair> pairNodes(const Eigen::MatrixXd& positions, const std::vector<int>& slave_nodes,
                                const std::vector<int>& master_nodes, const Eigen::MatrixXd& master_normals,
                                const Eigen::VectorXd& common_normal);

/// The master group's boundary facets (edges, triangles), oriented as the mesh's boundary: outward
/// normal (t_y, −t_x) of an edge, (x1 − x0) × (x2 − x0) of a triangle.
std::vector<std::vector<int>> masterFacets(const TriMesh& mesh, const std::string& group);
std::vector<std::vector<int>> masterFacets(const TetMesh& mesh, const std::string& group);

/// Node to segment (see above): the point of a master facet on the line through each slave node along
/// the unit `common_normal`. Throws InputError naming the node when no facet facing the slave meets
/// that line on the master's side.
std::vector<NodePair> pairNodesToFacets(const Eigen::MatrixXd& positions, const std::vector<int>& slave_nodes,
                                        const std::vector<std::vector<int>>& master_facets,
                                        const Eigen::VectorXd& common_normal);

}  // namespace stc
