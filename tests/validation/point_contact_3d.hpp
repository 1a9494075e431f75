#pragma once
// Shared pieces of the 3D point-contact validations (test_hertz_3d.cpp, test_cattaneo_3d.cpp): the
// half-ball with a uniformly meshed core (src/mesh/half_ball.hpp, HalfBallOptions::core) pressed onto
// the rigid flat, then optionally driven sideways, and the moment estimate of the radius of a
// hemispherical traction from nodal forces.
#include <Eigen/Core>
#include <vector>

#include "stcontact/contact/contact_state.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc::validation {

/// R = 1, E = 3000. The top face moves down by g0 + δ over the first `press_steps` instants, then
/// sideways (along x) by `drive` over `slide_steps` more; u_y = 0 throughout.
struct PointContactSetup {
  int divisions = 4;      ///< cells along the core's half-width
  double core = 0.07;     ///< core half-width / R (≈ the Hertz radius a = √(R δ) = 0.071 R)
  double poisson = 0.3;
  double friction = 0.0;
  int press_steps = 1;
  int slide_steps = 0;
  double drive = 0.0;
  bool pair = false;      ///< two identical half-balls, node to node (tests/fixtures/two_bodies_scene.hpp)
};
inline constexpr double kPointIndentation = 0.005;  ///< δ beyond first contact: a ≈ √(R δ) ≈ 0.07 R

Scene pointContactScene(const PointContactSetup& setup);

/// Reference position (x, y) of every potential contact node, and the core's cell size s0 R / m.
std::vector<Eigen::Vector2d> contactXY(const Problem& problem);
double coreCellSize(const Scene& scene);

/// Centre and radius of a traction known through nodal forces w_i ≥ 0 at nodes x_i, assuming the
/// hemispherical law w(x) ∝ √(1 − |x − e|²/c²) (Hertz pressure; Mindlin's stick-zone traction
/// deficit): its second central moment ∫ w |x − e|² dA / ∫ w dA is 2c²/5, so
///   c² = 5/2 (Σ w |x|² / Σ w − |e|²),  e = Σ w x / Σ w.
/// Not quantised by the node spacing (the last loaded node is); averages the nodal ripple.
struct DiscFit {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.0;
  double total = 0.0;
};
DiscFit discFromMoments(const std::vector<Eigen::Vector2d>& x, const std::vector<double>& w);

/// Total reactions at instant k: normal Σ λ_n and tangential Σ λ_t (in the node frames, which are all
/// (e_x, e_y, e_z) on the flat, asserted by the caller).
struct Resultant3d {
  double normal = 0.0;
  Eigen::Vector2d tangential = Eigen::Vector2d::Zero();
};
Resultant3d resultant3d(const Problem& problem, const Eigen::MatrixXd& lambda, int k);

/// Open / stick / slip of every node at instant k from |λ_t| and |Δv_t| in the tangent plane, with
/// the history's largest |λ| and |v| as scales (as the writers classify them).
std::vector<ContactState> contactStates3d(const Problem& problem, const InterfaceHistory& h, int k);

}  // namespace stc::validation
