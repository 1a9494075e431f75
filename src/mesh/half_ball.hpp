#pragma once
// Built-in generator for the three-dimensional counterpart of the seed scene's body: the half-ball
// x² + y² + z² ≤ R², z ≤ 0, meshed with P1 tetrahedra. The flat face is the top (z = 0), the
// curved surface lies below and touches a rigid plane at its bottom pole (0, 0, −R).
#include "src/mesh/tet_mesh.hpp"

namespace stc {

struct HalfBallOptions {
  double radius = 1.0;  ///< R > 0
  int divisions = 8;    ///< d >= 2: cells along the radius (2d × 2d × d cells of the reference box)
  double grading = 1.5;  ///< exponent p in [1, 2] of the refinement toward the bottom pole (1: none)
  void validate() const;  ///< throws InputError naming the field
};

/// Three maps of a structured grid of the box Q = [−1, 1]² × [−1, 0] (2d × 2d × d cubes, each split
/// into 6 tetrahedra around its diagonal that points away from the centre O of the top face, so
/// that neighbouring cubes share their face diagonals and the planes |x| = |y|, |x| = |z|,
/// |y| = |z|, where map 2 has kinks, are made of element faces before map 1):
///  1. grading toward the pole P = (0, 0, −1): v = x − P ↦ P + s^{p−1} v with s = ‖v‖_∞ (Q is the
///     half-box s ≤ 1 above P, so Q and each of its faces are kept; element sizes near P scale
///     like d^{−p}; its Jacobian s^{p−1}(I + (p − 1) v ∇sᵀ / s) stretches one direction at most p times
///     more than the others: the power grading used for point singularities);
///  2. the box onto the half unit ball: x ↦ x ‖x‖_∞ / ‖x‖₂ (the five faces other than z = 0 go
///     onto the hemisphere, the face z = 0 onto the unit disc);
///  3. scaling by R.
/// Every tetrahedron keeps a positive volume for d = 2..40 and p in {1, 1.1, 1.25, 1.5, 1.75, 2}
/// (checked by enumeration; beyond p = 2 elements near |x| = |y| = |z| invert at some d). The
/// generator validates its mesh and throws InputError if one does not.
/// Groups: "top" (the flat face z = 0) and "contact" (the curved surface, rim included). Surface
/// triangles are oriented outward. Node d + (2d + 1) d is the bottom pole.
TetMesh makeHalfBall(const HalfBallOptions& options);

}  // namespace stc
