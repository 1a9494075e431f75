#pragma once
// The assembled space-time problem of docs/method.md §1: stiffness, Dirichlet elimination, loads in
// separated form on the time grid, and the contact interface. Built once from a validated Scene.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <optional>
#include <string>
#include <vector>

#include "stcontact/contact/contact_interface.hpp"
#include "stcontact/mesh/body_mesh.hpp"
#include "stcontact/scene/model_spec.hpp"

namespace stc {

/// One separated term of the loading: at instant t_k the free dofs receive `free_force · values[k]`
/// and the full displacement gets `prescribed · values[k]`. A Dirichlet history u_d(t) on a set of
/// dofs D gives prescribed = e_D and free_force = −K_fD e_D; an applied force gives prescribed = 0.
/// Storing loads this way keeps memory O(n + m) per history instead of O(n·m).
struct SeparatedLoad {
  Eigen::VectorXd free_force;  ///< n_free
  Eigen::VectorXd prescribed;  ///< n (full field), zero on free dofs
  std::vector<double> values;  ///< m, the history sampled on the grid
};

struct Problem {
  std::string name;
  int dimension = 2;                          ///< d: 2 (triangles) or 3 (tetrahedra), dimensionOf(body)
  BodyMesh body;                              ///< the body's mesh
  MaterialSpec material;                      ///< the body's (with two bodies, the slave's)
  /// Two bodies of different materials ([master_material]): the master body's, and per element 1
  /// when it belongs to the master body (empty: `material` everywhere).
  std::optional<MaterialSpec> master_material;
  std::vector<char> master_elements;
  PlaneModel plane = PlaneModel::Strain;      ///< 2D only
  std::vector<double> times;                  ///< t_0 … t_{m−1}
  Eigen::SparseMatrix<double> stiffness;      ///< full, unconstrained K (n × n), for energies
  Eigen::SparseMatrix<double> stiffness_free; ///< K_ff (n_free × n_free)
  std::vector<int> free_dofs;                 ///< free dof ids, increasing
  std::vector<int> free_index;                ///< per dof: its index among free dofs, −1 if prescribed
  std::vector<SeparatedLoad> loads;
  ContactInterface contact;
  double length_scale = 1.0;                  ///< L of the search direction
  /// The obstacle's rigid translation d(t_k) (d × m; empty: a fixed obstacle). The problem is posed
  /// in the obstacle's frame: u' = u − d(t) has the same strains (a rigid translation has none), the
  /// gaps g0 + n · u' and the slips relative to the obstacle, and the Dirichlet values u_d − d(t)
  /// (docs/scene_format.md, `obstacle.motion`). Every solver works on u'; absoluteDisplacement
  /// gives u back for the outputs.
  Eigen::MatrixXd frame_motion;

  int numNodes() const { return stc::numNodes(body); }
  int numElements() const { return stc::numElements(body); }
  int numDofs() const { return dimension * numNodes(); }
  /// Node coordinates, d × numNodes().
  Eigen::MatrixXd nodePositions() const { return stc::nodePositions(body); }
  int numFreeDofs() const { return static_cast<int>(free_dofs.size()); }
  int numSteps() const { return static_cast<int>(times.size()); }

  /// f(t_k) on the free dofs: external forces minus K_fp u_p(t_k).
  Eigen::VectorXd load(int k) const;
  /// [f(t_0) … f(t_{m−1})] restricted to the instants [k0, k0 + count).
  Eigen::MatrixXd loadBlock(int k0, int count) const;
  /// Full displacement at instant k from the free part (in the obstacle's frame when it moves).
  Eigen::VectorXd fullDisplacement(const Eigen::VectorXd& u_free, int k) const;
  /// The same with the obstacle's translation added back to every node: the displacement in the
  /// scene's fixed frame (the outputs').
  Eigen::VectorXd absoluteDisplacement(const Eigen::VectorXd& u_free, int k) const;
  /// Adds the obstacle's translation at instant k to every node of the full displacement u: from
  /// its frame to the scene's (nothing for a fixed obstacle).
  void addFrameMotion(Eigen::Ref<Eigen::VectorXd> u, int k) const;
};

/// Builds the mesh (triangles or tetrahedra, by scene.dimension), assembles K, eliminates Dirichlet dofs, samples the histories and sets up the
/// contact interface with k = κ E ℓ_i / L. Throws InputError on inconsistent input (a boundary that
/// the mesh lacks, a dof prescribed twice, initial penetration, a contact node half prescribed).
Problem buildProblem(const ModelSpec& scene);

/// The scene's mesh in `dimension`: a built-in generator (half_disc in 2D; half_ball, half_disc_slab in
/// 3D) or a Gmsh file.
BodyMesh buildBodyMesh(const MeshSpec& spec, int dimension);

}  // namespace stc
