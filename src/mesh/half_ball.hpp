#pragma once
// Built-in generator for the three-dimensional counterpart of the seed scene's body: the half-ball
// x² + y² + z² ≤ R², z ≤ 0, meshed with P1 tetrahedra. The flat face is the top (z = 0), the
// curved surface lies below and touches a rigid plane at its bottom pole (0, 0, −R).
#include "stcontact/mesh/tet_mesh.hpp"

namespace stc {

struct HalfBallOptions {
  double radius = 1.0;  ///< R > 0
  int divisions = 8;    ///< d >= 2: cells along the radius (2d × 2d × d cells of the reference box)
  double grading = 1.5;  ///< exponent p in [1, 2] of the refinement toward the bottom pole (1: none)
  double core = 0.0;     ///< 0, or the half-width s0 / R of a uniformly meshed core, s0 < d / (2d + 1) (below)
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
/// With core = s0 > 0 (point-contact validation: the contact zone needs elements of one size h down
/// to a depth of a few contact radii, and the power grading cannot give them without anisotropy)
/// the grading map is replaced by a locally refined box, made of three parts:
///  - the core: the half-box ‖x − P‖_∞ <= s0 meshed as the structured grid above with d = divisions,
///    scaled by s0 about P (h = s0 R / d, uniform);
///  - L shells: copies of the core's outer surface scaled about P by s0 (s1/s0)^{l/L}, l = 1..L − 1,
///    with s1 = d / (2d + 1) and L = ⌈ln(s1/s0) / ln(1 + 1/d)⌉, so that each layer's thickness
///    matches its surface's cell size (elements grow geometrically away from the core); a shell's
///    prisms (surface triangle × layer step) are split into 3 tetrahedra by the rule "each side
///    quad's diagonal leaves its lowest-numbered vertex", conforming by construction;
///  - the outer grid: the structured grid of 2d + 1 divisions without the cubes of its hole
///    ‖x − P‖_∞ < s1, whose surface is layer L (the same triangles as the core's, scaled).
/// s1 < 1/2 keeps the kinks |x| = |z|, |y| = |z| of map 2 out of the core and shells, where the
/// elements are not aligned with them (the kink |x| = |y| is made of element faces there). Needs
/// s0 < s1. No tetrahedron inverts for d = 4..12, s0 in {0.05, 0.1, 0.2, 0.4} (checked by enumeration).
/// Groups: "top" (the flat face z = 0) and "contact" (the curved surface, rim included). Surface
/// triangles are oriented outward. Node d + (2d + 1) d is the bottom pole.
TetMesh makeHalfBall(const HalfBallOptions& options);

/// The nodes makeHalfBall would create, in floating point: (2d + 1)² (d + 1) for the graded grid; with
/// a core, at most three times the outer grid of 2d + 1 divisions.
double halfBallNodeCount(const HalfBallOptions& options);

}  // namespace stc
