#pragma once
// Options of `fas-aposteriori`: the two-level FAS whose coarse space is the seed's a posteriori basis
// (seed §4.2–4.3; docs/method.md §4): SVD modes of a converged solution, plus residual vectors.
#include "stcontact/options/fas_options.hpp"
#include "stcontact/options/option_fields.hpp"

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

struct FasAposterioriOptions {
  FasOptions fas;
  AposterioriBasisOptions basis;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    FasOptions::fields(o.fas, visit);
    AposterioriBasisOptions::fields(o.basis, visit);
  }
  void validate() const {
    fas.validate();
    basis.validate();
  }
};

}  // namespace stc::fas
