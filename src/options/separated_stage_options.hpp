#pragma once
// Options of the separated global stage with its error controlled (pgd/controlled_global_stage.hpp;
// docs/method.md §5), the fine level of `latin-pgd` and `fas-apriori`.
#include "stcontact/options/option_fields.hpp"

namespace stc::pgd {

struct ControlledStageOptions {
  /// γ: the projection error is kept below γ times the previous iteration's gap ‖s − ŝ‖. Must be
  /// small against 1 − ρ (LATIN's rate ρ ≈ 0.9 on the seed scene); 0.05 measured in docs/floor.md.
  double gap_share = 0.05;
  /// Share of the interface rows d n_C from which the directions are completed to span them all
  /// when the factor gives D = B A⁻¹ Bᵀ (pgd/controlled_global_stage.hpp, "Every row"): 1 completes
  /// only a basis the enrichment has filled.
  double full_share = 0.3;
  /// Share of the memory available to a rank (its share of MemAvailable) that the directions'
  /// responses X (n_free × p) may hold where the factor does not condense the interface; beyond, the
  /// traces alone are kept and the modes solved again when asked for (pgd/response_basis.hpp). The
  /// iterates do not depend on it. 0.25 leaves room for the factor or preconditioner and the histories.
  double response_share = 0.25;
  /// L: the most a direction's relative residual may be loosened on an iterative backend,
  /// ρ_j = min(ℓ_j ρ, 1e-4) with ℓ_j ≤ L (pgd/controlled_global_stage.hpp, "Inexact directions");
  /// 1 solves every direction to ρ. 1e6 reaches the 1e-4 ceiling at the default ρ = 1e-4 τ, τ = 1e-6.
  double loosening_cap = 1e6;
  int block = 8;             ///< directions added per enrichment pass at most
  int oversampling = 4;      ///< extra random samples of the range finder
  int power_iterations = 1;  ///< subspace iterations of the range finder

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    visit("pgd_gap_share", o.gap_share, inOpenUnit());
    visit("pgd_full_share", o.full_share, inUnitHalfOpen());
    visit("pgd_response_share", o.response_share, inUnitClosed());
    visit("pgd_loosening_cap", o.loosening_cap, atLeast(1));
    visit("block", o.block, atLeast(1), Exposure::Library);
    visit("oversampling", o.oversampling, atLeast(0), Exposure::Library);
    visit("power_iterations", o.power_iterations, atLeast(0), Exposure::Library);
  }
  void validate() const { validateFields(*this, "separated global stage"); }
};

}  // namespace stc::pgd
