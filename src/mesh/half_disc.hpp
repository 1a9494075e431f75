#pragma once
// Built-in generator for the seed scene's body (docs/method.md §6): the half-disc
// x² + y² ≤ R², y ≤ 0, meshed with P1 triangles in concentric half-rings.
#include "stcontact/mesh/tri_mesh.hpp"

namespace stc {

struct HalfDiscOptions {
  double radius = 1.0;  ///< R > 0
  int arc_nodes = 101;  ///< potential contact nodes strictly inside the arc (the corners are on `top`)
  double grading = 1.135;  ///< element size growth per ring inward, >= 1 (1: uniform size)
  void validate() const;  ///< throws InputError naming the field
};

/// Rings of radius r_j carry nodes at equal angles; ring 0 is the arc with arc_nodes + 1 segments
/// of length h_0 = πR/(arc_nodes + 1). Going inward, h_{j+1} = grading·h_j and the radial step is
/// the height of an equilateral triangle of side (h_j + h_{j+1})/2; neighbouring rings are joined by
/// a zipper triangulation and the innermost ring by a fan around the centre (0, 0).
/// Groups: "arc" (the curved edge, corners included) and "top" (the flat edge y = 0).
TriMesh makeHalfDisc(const HalfDiscOptions& options);

/// The nodes makeHalfDisc would create, counted in floating point without building them (its rings,
/// at most as many segments as the one outside, and the centre); the count stops above 1e12.
double halfDiscNodeCount(const HalfDiscOptions& options);

}  // namespace stc
// Sizes (tests/mesh/test_half_disc.cpp checks them): arc_nodes = 101 with the default grading
// 1.135 gives 571 nodes, 1142 dofs, 1012 triangles (the seed paper: 1144 dofs), minimum angle 30°.
