#pragma once
// The locally refined box of the half-ball generator with a core (src/mesh/half_ball.hpp,
// HalfBallOptions::core): a uniform core around the bottom pole wrapped in geometric shells.
#include "stcontact/mesh/tet_mesh.hpp"

namespace stc::detail {

/// The tetrahedra of the reference box [−1, 1]² × [−1, 0] with a core of half-width `core` around
/// P = (0, 0, −1) meshed by `divisions` cells along it; nodes in box coordinates, no groups. The
/// core's nodes come first, numbered as BoxGrid(divisions) numbers them.
TetMesh coredBox(int divisions, double core);

}  // namespace stc::detail
