#pragma once
// LATIN's search direction k_i = κ E ℓ_i / L (docs/method.md §2, docs/search_direction.md): its
// scale κ (solver.search_scale) and how it is spread over the contact nodes (solver.search_law). A
// property of the problem every LATIN-based strategy iterates on (Problem::contact.search_direction),
// so it belongs to the model, not to a strategy's options, though the scene sets it under [solver].
#include <array>
#include <string_view>
#include <utility>

#include "stcontact/options/option_fields.hpp"

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

struct SearchDirectionOptions {
  /// κ of k = κ E ℓ_i / L; 4 from docs/search_direction.md.
  double scale = 4.0;
  /// The local law, which is the tributary one where every contact facet has one size and follows
  /// the facet size on graded meshes (docs/search_direction.md "The local law").
  SearchLaw law = SearchLaw::Local;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    visit("search_scale", o.scale, positive());
    visit("search_law", o.law, Keywords<SearchLaw>(kSearchLaws));
  }
  void validate() const { validateFields(*this, "solver"); }
};

}  // namespace stc
