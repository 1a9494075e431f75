#pragma once
// What the model is built from (src/problem/problem.hpp, buildProblem): the body, its material, the
// obstacle or the second body, the contact, the time grid, the prescribed histories and the search
// direction, as the scene file gives them (docs/scene_format.md), validated, nothing computed. The
// strategies' options and the outputs are the rest of a Scene (scene.hpp): the model does not
// depend on them. Units are the user's (the seed scene: mm, MPa, N/mm); times are dimensionless
// instants.
#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "stcontact/options/search_direction_options.hpp"

namespace stc {

enum class PlaneModel { Strain, Stress };
enum class Component { X, Y, Z };  ///< Z only in a 3D scene

/// The dof of `c` within a node's d dofs: x 0, y 1, z 2.
inline int componentIndex(Component c) { return c == Component::X ? 0 : c == Component::Y ? 1 : 2; }

/// [mesh]: either a built-in generator or a Gmsh 4.1 file.
struct MeshSpec {
  std::string generator;              ///< "half_disc" (2D), "half_ball" or "half_disc_slab" (3D), or empty
                                      ///< when `file` is given
  std::filesystem::path file;         ///< resolved against the scene file's folder
  double radius = 1.0;                ///< half_disc, half_ball: radius R (> 0)
  int arc_nodes = 101;                ///< half_disc, half_disc_slab: potential contact nodes on the arc (>= 3)
  double grading = 1.135;             ///< half_disc: growth of the element size per ring inward (1 = uniform);
                                      ///< half_ball: grading toward the pole, in [1, 2] (default 1.5)
  int divisions = 8;                  ///< half_ball: cells along the radius (>= 2; src/mesh/half_ball.hpp)
  double thickness = 0.05;            ///< half_disc_slab: extent along z (> 0)
  int layers = 2;                     ///< half_disc_slab: element layers along z (>= 1)
  double core = 0.0;                  ///< half_ball: 0, or the half-width in (0, 1) of the uniformly meshed
                                      ///< core around the pole, in units of R (divisions then counts its cells)
  /// Two bodies: the mesh and its mirror image this far below it (>= 0; src/mesh/mirror_image.hpp),
  /// the image's groups named "mirror_" + the mesh's. None: one body.
  std::optional<double> mirror_gap;
};

/// ν's range: 1 + ν ≥ 1e-6 and 1 − 2ν ≥ 1e-6. The stiffness grows as 1 / (1 + ν) toward −1 and
/// as 1 / (1 − 2ν) toward 0.5 against E, and the search direction (k = κ E ℓ / L) and the error's
/// energy are resolved in double precision within a contrast of 1e6: beyond it `fas-apriori` and
/// `fas-aposteriori` reported converged at true errors of 0.22 (ν = −1 + 1e-8) and 8.7e-6 against
/// τ = 1e-6 (ν = 0.5 − 1e-11) on the seed scene, where every other solve ended unconverged
/// (docs/reliability.md).
inline constexpr double kPoissonLow = -1.0 + 1e-6;
inline constexpr double kPoissonHigh = 0.5 - 0.5e-6;

/// [material]: isotropic linear elasticity.
struct MaterialSpec {
  double young = 0.0;    ///< E > 0
  double poisson = 0.0;  ///< ν in [kPoissonLow, kPoissonHigh]
};

/// Plane (2D and 3D); sphere (3D) and cylinder (2D: its cross-section, a circle): a ball; polyline
/// (2D): a rigid profile given by its points; surface (3D): a triangulated surface from a Gmsh file.
enum class ObstacleType { Plane, Sphere, Cylinder, Polyline, Surface };

/// One piecewise-linear history of a scalar: `times` strictly increasing, same length as `values`.
struct History {
  std::vector<double> times;
  std::vector<double> values;
};

/// [[obstacle.motion]]: the obstacle's rigid translation along `component` (docs/scene_format.md).
struct ObstacleMotionSpec {
  Component component = Component::X;
  History history;
};

/// [obstacle]: rigid obstacle. Plane: through `point` with unit `normal` pointing into the body,
/// both with the scene's dimension of entries. Sphere, cylinder: `centre` and `radius`, the solid
/// ball the body lies outside of, or with `inside` the ball's complement, a seat the body lies in.
struct ObstacleSpec {
  ObstacleType type = ObstacleType::Plane;
  Eigen::VectorXd point = Eigen::VectorXd::Zero(2);
  Eigen::VectorXd normal = Eigen::VectorXd::Unit(2, 1);  ///< normalised on reading (must be nonzero)
  Eigen::VectorXd centre = Eigen::VectorXd::Zero(2);     ///< sphere, cylinder
  double radius = 0.0;                                    ///< sphere, cylinder: > 0
  bool inside = false;  ///< sphere, cylinder: the body inside the ball; surface: on the side its
                        ///< triangles' normals point away from (side = "inside")
  std::filesystem::path file;  ///< surface: the Gmsh surface mesh, resolved against the scene's folder
  Eigen::Matrix2Xd points;  ///< polyline: its points (≥ 2, consecutive ones distinct), the body on the left
  /// Its rigid translation d(t), one history per component (none: fixed). The problem is solved in
  /// the obstacle's frame (src/problem/problem.hpp, Problem::frame_motion).
  std::vector<ObstacleMotionSpec> motion;
};

/// [contact]: which boundary may touch the obstacle, with which Coulomb coefficient; or, with
/// `master`, which two boundaries of two bodies of the mesh may touch each other (node to node,
/// src/contact/node_pairing.hpp; the scene then has no [obstacle]).
struct ContactSpec {
  std::string boundary;                 ///< the body's contact boundary; with `master`, the slave's
  std::string master;                   ///< empty: a rigid obstacle; else the other body's boundary
  Eigen::VectorXd normal;               ///< with `master`: the common normal from the master into the
                                        ///< slave along which nodes pair (unit), or empty: the nearest
  /// With `master`: each slave node pairs with a master node (matching meshes) or, with `segment`, with
  /// the point of a master facet (edge, triangle) on its line along `normal` (non-matching meshes).
  bool to_segment = false;
  double friction = 0.0;                ///< mu >= 0
  std::optional<double> length_scale;  ///< L of the search direction k = kappa E l_i / L (> 0);
                                        ///< default: the radius, or half the mesh's largest extent
};

/// [time]: uniform grid of `steps` instants on [0, end].
struct TimeSpec {
  int steps = 0;       ///< m >= 2
  double end = 1.0;    ///< > 0
};

/// [[dirichlet]]: prescribed displacement component on every node of a boundary.
struct DirichletSpec {
  std::string boundary;
  Component component = Component::X;
  History history;
};

/// What a [[load]] entry's history gives (src/problem/distributed_loads.hpp).
enum class LoadKind {
  Force,     ///< the total force on a boundary along `component`, spread by edge length / face area
  Pressure,  ///< a pressure on a boundary, per unit length (2D) or area (3D), along the inward normal
  Body,      ///< a force per unit area (2D) or volume (3D) on the whole body, along `component`
};

/// [[load]]: total force on a boundary (per unit thickness in 2D), spread by edge length (2D) or
/// face area (3D); or a pressure on a boundary; or a body force (`type`).
struct LoadSpec {
  std::string boundary;                ///< force, pressure
  Component component = Component::X;  ///< force, body
  History history;
  LoadKind kind = LoadKind::Force;
};

struct ModelSpec {
  std::string name;
  std::filesystem::path source;  ///< the scene file, for messages and relative paths
  int dimension = 2;             ///< 2 (plane, P1 triangles) or 3 (P1 tetrahedra)
  PlaneModel plane = PlaneModel::Strain;  ///< 2D only
  MeshSpec mesh;
  MaterialSpec material;         ///< the body's; with two bodies, the slave body's (and the master's by default)
  /// [master_material]: the master body's, with contact.master only (none: [material]).
  std::optional<MaterialSpec> master_material;
  ObstacleSpec obstacle;         ///< unused when contact.master names a second body
  ContactSpec contact;
  TimeSpec time;
  std::vector<DirichletSpec> dirichlet;
  std::vector<LoadSpec> loads;
  /// solver.search_scale and solver.search_law: the search direction every LATIN-based strategy
  /// iterates on, a property of the problem (Problem::contact.search_direction).
  SearchDirectionOptions search_direction;
};

}  // namespace stc
