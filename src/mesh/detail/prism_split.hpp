#pragma once
// A prism (triangle × one layer step) into 3 tetrahedra, conforming with its neighbours without any
// bookkeeping: used by the extruded slab (src/mesh/half_disc_slab.hpp) and the cored half-ball's shells
// (src/mesh/detail/cored_box.cpp).
#include <array>
#include <vector>

namespace stc::detail {

/// Prism (a, b, c) × (lower layer, upper layer), its triangle's vertices in ascending order of a
/// numbering shared by the whole layer (a < b < c), into 3 tetrahedra whose side-quad diagonals
/// leave the quad's lowest vertex on the lower layer (a of ab, b of bc, a of ac): the prism that
/// shares a side quad draws the same diagonal, so the mesh is conforming (the classical rule of
/// Dompierre et al., "How to subdivide pyramids, prisms and hexahedra into tetrahedra", 1999).
/// `lower` and `upper` hold the node ids of a, b, c on the two layers. The tetrahedra are not
/// oriented.
inline void splitPrism(const std::array<int, 3>& lower, const std::array<int, 3>& upper,
                       std::vector<std::array<int, 4>>& tets) {
  const auto [a, b, c] = lower;
  const auto [a1, b1, c1] = upper;
  tets.push_back({a, b, c, c1});
  tets.push_back({a, b, b1, c1});
  tets.push_back({a, a1, b1, c1});
}

}  // namespace stc::detail
