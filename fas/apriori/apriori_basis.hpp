#pragma once
// The a priori coarse space of `fas-apriori` (docs/method.md §5): built from the fine level's own
// iterate, never from a converged solution. The fine level's global stage is separated and
// controlled (pgd/controlled_global_stage.hpp): its displacement history is u_k = U_F g_k + X c_k,
// with spatial modes X = A⁻¹ Bᵀ Z enriched during the iterations. Each cycle the provider
// recompresses that expansion by its energy SVD (pgd/separated_history.hpp) and offers
//   - the `modes` leading A-orthonormal modes of ũ (the space the solution lives in, ordered like
//     the SVD of a converged solution once ũ has converged), and
//   - the `increment_modes` leading modes of what ũ changed since the previous coarse step, made
//     A-orthogonal to the former (the directions the iteration is still moving in: the seed's
//     residual vectors, §4.3, taken from the iterates' history instead of the iterate itself),
//     and of `step_samples` Gaussian combinations of the change the next global stage makes,
//     ũ − ũ_last (ControlledGlobalStage::anticipateWhitened: the direction the smoother moves in
//     now, where ũ − ũ_previous sums a whole cycle),
// as a coarse space known by its traces B Y alone: no n_free × m array, no product with A.
// With `anticipate` (the default) ũ is the displacement history the next global stage would give:
// the projection of its right-hand side λ̂ + k v̂ on the directions, enriched as that stage would
// enrich it (ControlledGlobalStage::anticipate), so the directions the next relaxation needs are in
// the coarse step already (docs/method.md §5, "The anticipated expansion").
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>

#include "stcontact/fas/basis_provider.hpp"
#include "stcontact/options/fas_apriori_options.hpp"
#include "stcontact/pgd/controlled_global_stage.hpp"

namespace stc::fas {

class AprioriBasisProvider : public BasisProvider {
 public:
  /// With options.anticipate the provider enriches `stage`'s directions (coarseSpace).
  AprioriBasisProvider(pgd::ControlledGlobalStage& stage, AprioriBasisOptions options);
  CoarseSpace coarseSpace(const InterfaceHistory& hat) override;
  bool anticipates() const override { return options_.anticipate; }

 private:
  pgd::ControlledGlobalStage& stage_;
  AprioriBasisOptions options_;
  Eigen::MatrixXd previous_;  ///< whitened coordinates Θ̂ = R [G; c] of ũ at the previous coarse step
};

/// Where the coarse spaces of `fas-apriori`'s pipeline (its separated stage, reduced interface and
/// nested iteration in time: fas/apriori/solve_fas_apriori.hpp) come from: the strategy named in the
/// summary, and the provider built on the stage of each solve of the pipeline and its problem. An empty
/// `make` is the a priori provider with the options' basis; `fas-aposteriori` on the separated fine
/// level (fas/aposteriori/) gives its own, so that both bases run on the same fine level.
struct SeparatedCoarseBasis {
  std::string solver = "fas-apriori";
  std::function<std::unique_ptr<BasisProvider>(pgd::ControlledGlobalStage&, const Problem&)> make;

  std::unique_ptr<BasisProvider> providerOn(pgd::ControlledGlobalStage& stage, const Problem& problem,
                                            const AprioriBasisOptions& apriori) const;
};

}  // namespace stc::fas
