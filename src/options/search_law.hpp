#pragma once
// How the search direction k_i of LATIN's local stage is spread over the contact nodes
// (docs/method.md §2, docs/search_direction.md "Graded meshes"): solver.search_law.
#include <array>
#include <string_view>
#include <utility>

namespace stc {

enum class SearchLaw {
  /// k_i = κ E ℓ_i / L: proportional to the node's tributary measure ℓ_i (length in 2D, area in 3D).
  Tributary,
  /// k_i = κ E ℓ_i h̄ / (L h_i), h_i the mean size of the contact facets at node i (an edge's length in
  /// 2D, √area of a triangle in 3D) and h̄ = Σ ℓ_i / Σ (ℓ_i / h_i), so that Σ k_i is the tributary
  /// law's: k_i grows as the local stiffness E h_i in 3D and stays E in 2D where the mesh is graded,
  /// and is the tributary law where every facet has one size (a node at a patch's edge keeps half).
  Local,
};

inline constexpr std::array<std::pair<std::string_view, SearchLaw>, 2> kSearchLaws = {{
    {"tributary", SearchLaw::Tributary},
    {"local", SearchLaw::Local},
}};

}  // namespace stc
