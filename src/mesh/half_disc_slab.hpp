#pragma once
// Built-in 3D generator: the seed scene's half-disc (src/mesh/half_disc.hpp) extruded along z, a
// slab whose plane-strain state (u_z = 0 on both faces) is the 2D seed problem: the same physics
// through the 3D code path.
#include "stcontact/mesh/half_disc.hpp"
#include "stcontact/mesh/tet_mesh.hpp"

namespace stc {

struct HalfDiscSlabOptions {
  HalfDiscOptions section;  ///< the cross-section in the (x, y) plane
  double thickness = 0.05;  ///< extent along z, > 0
  int layers = 2;           ///< element layers along z, >= 1
  void validate() const;    ///< throws InputError naming the field
};

/// Node n of the half-disc on layer l (0..layers) is node n + l N_2D at (x_n, y_n, l · thickness /
/// layers); each triangle × layer step is a prism split into 3 tetrahedra by the rule of
/// src/mesh/detail/prism_split.hpp (with the half-disc's own node numbering), so layers and
/// neighbours conform. Groups: "arc" and "top" (the half-disc's, extruded), "front" (z = 0) and
/// "back" (z = thickness); surface triangles oriented outward.
TetMesh makeHalfDiscSlab(const HalfDiscSlabOptions& options);

}  // namespace stc
