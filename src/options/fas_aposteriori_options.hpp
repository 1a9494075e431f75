#pragma once
// Options of `fas-aposteriori`: the two-level FAS whose coarse space is the seed's a posteriori basis
// (seed §4.2–4.3; docs/method.md §4): SVD modes of a converged solution, plus residual vectors.
#include "stcontact/options/fas_apriori_options.hpp"
#include "stcontact/options/fas_options.hpp"
#include "stcontact/options/option_fields.hpp"
#include "stcontact/options/separated_stage_options.hpp"

namespace stc::fas {

struct AposterioriBasisOptions {
  int svd_modes = 10;         ///< leading energy-SVD modes of the converged solution (seed §4.3)
  int residual_vectors = 15;  ///< N_res: residual vectors renewed every cycle (seed §4.3)

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    visit("svd_modes", o.svd_modes, atLeast(0));
    visit("residual_vectors", o.residual_vectors, atLeast(0));
  }
  void validate() const { validateFields(*this, "a posteriori basis"); }
};

/// The fine level the a posteriori coarse space corrects.
enum class AposterioriFineLevel {
  Full,       ///< the exact global stage on the whole interface (seed §4: one sparse solve per instant)
  Separated,  ///< `fas-apriori`'s: the separated stage, reduced interface, nested iteration in time
};
inline constexpr std::array<std::pair<std::string_view, AposterioriFineLevel>, 2> kAposterioriFineLevels = {{
    {"full", AposterioriFineLevel::Full},
    {"separated", AposterioriFineLevel::Separated},
}};

/// The options of the separated fine level (its base, SeparatedFineLevelOptions) act on it only.
struct FasAposterioriOptions : SeparatedFineLevelOptions {
  FasOptions fas;
  AposterioriBasisOptions basis;
  /// Full: the seed paper's FAS. Separated: the same fine level as `fas-apriori` (the base's options,
  /// shared with it), so that the two differ by their basis alone (docs/compare_bases.md).
  AposterioriFineLevel fine_level = AposterioriFineLevel::Full;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    FasOptions::fields(o.fas, visit);
    AposterioriBasisOptions::fields(o.basis, visit);
    visit("aposteriori_fine_level", o.fine_level, Keywords<AposterioriFineLevel>(kAposterioriFineLevels));
    SeparatedFineLevelOptions::fields(o, visit);
  }
  void validate() const {
    fas.validate();
    basis.validate();
    SeparatedFineLevelOptions::validate();
  }
};

}  // namespace stc::fas
