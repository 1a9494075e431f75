#pragma once
// The discrete contact interface of docs/method.md §1: potential contact nodes facing a rigid obstacle,
// or paired with the nodes of another body (node to node), their frames, initial gaps, tributary
// measures, the operator B and the LATIN search direction k.
// A node has d = 2 or 3 rows (the scene's dimension): one normal, then d − 1 tangential.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "stcontact/contact/obstacle.hpp"
#include "stcontact/mesh/tet_mesh.hpp"
#include "stcontact/mesh/tri_mesh.hpp"
#include "stcontact/options/search_direction_options.hpp"

namespace stc {

struct ContactInterface {
  int dimension = 2;               ///< d: rows per node (normal + d − 1 tangential)
  std::vector<int> nodes;          ///< mesh node id of each potential contact node i = 0..n_C−1
  /// Two bodies: the mesh node id of the master node paired with node i (node to segment: the node of
  /// its master facet with the largest weight); empty against a rigid obstacle.
  std::vector<int> master_nodes;
  /// Two bodies: the master nodes node i is compared with, column i (node to node: one row, the master
  /// node; node to segment: d rows, its master facet's nodes of nonzero weight, then −1), and their
  /// weights w_j (then 0; Σ_j w_j = 1). B rows of node i carry −w_j n, −w_j τ on master node j:
  /// v = relative displacement u_i − Σ_j w_j u_j (contact/node_pairing.hpp). Empty for a rigid obstacle.
  Eigen::MatrixXi master_facets;
  Eigen::MatrixXd master_weights;
  Eigen::MatrixXd normals;         ///< n_i (d × n_C), from the obstacle into the body
  /// Tangential directions, d × (d − 1) n_C: column (d − 1) i + a is τ_{i,a}. 2D: τ = (n_y, −n_x);
  /// 3D: τ_1 = the unit projection of the least aligned coordinate axis (e_x first) on the tangent
  /// plane, τ_2 = n × τ_1, so that (τ_1, τ_2, n) is right-handed.
  Eigen::MatrixXd tangents;
  Eigen::VectorXd initial_gap;     ///< g0_i = (x_i − x_obs)·n_i ≥ 0
  Eigen::VectorXd tributary;       ///< ℓ_i: half the contact-boundary edge lengths at node i (2D),
                                   ///< a third of the contact-boundary triangle areas (3D)
  Eigen::VectorXd facet_size;      ///< h_i: the mean size of the contact facets at node i (edge
                                   ///< length in 2D, √area in 3D)
  double friction = 0.0;           ///< Coulomb coefficient μ
  /// v = B u_free: row d i is the normal n_i·u_i, rows d i + a (a = 1..d−1) the tangential τ_{i,a}·u_i;
  /// d n_C × n_free.
  Eigen::SparseMatrix<double> B;
  /// Tangential rows whose direction is prescribed at zero (a symmetry plane, the faces of a slab):
  /// their B row is empty, the node cannot slip that way and the support takes the force (see
  /// buildContactInterface); sorted.
  std::vector<int> held_rows;
  /// Search direction k (d n_C, diagonal): the same k_i = κ E ℓ_i / L on every row of node i
  /// (docs/method.md §2; ℓ_i an area in 3D, so k_i is a stiffness in both), or with the local law
  /// κ E ℓ_i h̄ / (L h_i) (src/options/search_direction_options.hpp).
  Eigen::VectorXd search_direction;
  double search_scale_per_length = 0.0;  ///< κ E / L: k_i = search_scale_per_length · ℓ_i (tributary law)

  int size() const { return static_cast<int>(nodes.size()); }
  bool isPair() const { return !master_nodes.empty(); }
  int rows() const { return dimension * size(); }
  /// Row of the normal component of node i; its tangential rows follow.
  int normalRow(int i) const { return dimension * i; }
};

/// How the dofs are held: `free_index[dof]` is the dof's index among the free dofs (−1 when
/// prescribed), `zero[dof]` says that a prescribed dof is held at 0 at every instant.
struct DofStatus {
  const std::vector<int>& free_index;
  const std::vector<char>& zero;
};

/// Builds the interface on boundary group `boundary` of the mesh. A node of the group whose normal
/// motion is prescribed is left out (its motion is known and the support takes any force: the
/// half-disc's arc corners): every dof prescribed, or a prescribed axis along the obstacle normal
/// there (|n · e_a| = 1). A node may otherwise have prescribed components only along axes
/// orthogonal to its normal and held at 0 at every instant: such an axis is one of the node's
/// tangents (see `tangents`), whose row becomes a held row. Throws InputError for any other
/// partly prescribed node, or a node that starts inside the obstacle (g0 < 0).
ContactInterface buildContactInterface(const TriMesh& mesh, const std::string& boundary, const Obstacle& obstacle,
                                       const DofStatus& dofs, double friction);
/// The same on a tetrahedron mesh's surface group (3 rows per node).
ContactInterface buildContactInterface(const TetMesh& mesh, const std::string& boundary, const Obstacle& obstacle,
                                       const DofStatus& dofs, double friction);

/// Two bodies of one mesh: the slave group's nodes paired node to node with the master group's,
/// along `common_normal` when not empty, or with the points of its facets along it when `to_segment`
/// (contact/node_pairing.hpp), the same rule for prescribed
/// components as buildContactInterface; a master node may only be free or held at 0. Throws
/// InputError when the boundaries do not face each other, overlap or do not match.
ContactInterface buildContactPair(const TriMesh& mesh, const std::string& slave, const std::string& master,
                                  const Eigen::VectorXd& common_normal, bool to_segment, const DofStatus& dofs,
                                  double friction);
ContactInterface buildContactPair(const TetMesh& mesh, const std::string& slave, const std::string& master,
                                  const Eigen::VectorXd& common_normal, bool to_segment, const DofStatus& dofs,
                                  double friction);

/// The interface of nodes `nodes` (indices 0..n_C−1 of `contact`, kept in the given order, no
/// repeats): their frames, gaps, measures, search directions (when set), B rows and held rows,
/// renumbered.
/// Throws std::out_of_range for an index outside the interface.
ContactInterface restrictToNodes(const ContactInterface& contact, const std::vector<int>& nodes);

/// The rows d i … d i + d − 1 of each node i of `nodes`, in the nodes' order.
std::vector<int> rowsOfNodes(int d, const std::vector<int>& nodes);

/// The nodes 0 … n − 1 not in `nodes`, increasing.
std::vector<int> otherNodes(int n, const std::vector<int>& nodes);

/// The free dofs that B (rows × n_free) reads: its nonzero columns, increasing.
std::vector<int> dofsReadBy(const Eigen::SparseMatrix<double>& B);

/// A vector of the global frame: d ≤ 3 entries on the stack (one per node and instant in the writers).
using GlobalVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;

/// Node i's vector of components (normal, τ_1[, τ_2]) in the global frame: l_0 n_i + Σ_a l_a τ_{i,a}.
GlobalVector inGlobalFrame(const ContactInterface& contact, int i, const Eigen::Ref<const Eigen::VectorXd>& local);

/// Sets k_i = κ E ℓ_i / L (tributary law) or κ E ℓ_i h̄ / (L h_i) (local law,
/// src/options/search_direction_options.hpp) on every row of every node.
void setSearchDirection(ContactInterface& contact, double kappa, double young, double length_scale,
                        SearchLaw law = SearchLaw::Tributary);

}  // namespace stc
