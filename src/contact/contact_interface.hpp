#pragma once
// The discrete contact interface of docs/method.md §1: potential contact nodes facing a rigid obstacle,
// their frames, initial gaps, tributary lengths, the operator B and the LATIN search direction k.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "src/contact/obstacle.hpp"
#include "src/mesh/mesh.hpp"

namespace stc {

struct ContactInterface {
  std::vector<int> nodes;          ///< mesh node id of each potential contact node i = 0..n_C−1
  Eigen::Matrix2Xd normals;        ///< n_i, from the obstacle into the body
  Eigen::Matrix2Xd tangents;       ///< τ_i = (n_y, −n_x)
  Eigen::VectorXd initial_gap;     ///< g0_i = (x_i − x_obs)·n_i ≥ 0
  Eigen::VectorXd tributary;       ///< ℓ_i: half the length of the contact-boundary edges at node i
  double friction = 0.0;           ///< Coulomb coefficient μ
  /// v = B u_free: rows 2i (normal: n_i·u_i) and 2i + 1 (tangential: τ_i·u_i), 2n_C × n_free.
  Eigen::SparseMatrix<double> B;
  /// Search direction k (2n_C, diagonal): k_n = k_t = κ E ℓ_i / L (docs/method.md §2).
  Eigen::VectorXd search_direction;
  double search_scale_per_length = 0.0;  ///< κ E / L, so that k_i = search_scale_per_length · ℓ_i

  int size() const { return static_cast<int>(nodes.size()); }
};

/// Builds the interface on boundary group `boundary` of the mesh. Nodes of the group whose two
/// dofs are both prescribed are left out (their motion is known; the half-disc's arc corners);
/// `free_index[dof]` is the dof's index among the free dofs, −1 when prescribed. Throws InputError
/// for a node with only one prescribed dof, or a node that starts inside the obstacle (g0 < 0).
ContactInterface buildContactInterface(const Mesh& mesh, const std::string& boundary, const Obstacle& obstacle,
                                       const std::vector<int>& free_index, double friction);

/// Sets k = κ E ℓ_i / L on both directions of every node.
void setSearchDirection(ContactInterface& contact, double kappa, double young, double length_scale);

}  // namespace stc
