#pragma once
// LATIN's global stage in separated form (docs/method.md §5): s ∈ A_d sought as u(t_k) = Σ_j Υ_j ψ_j(t_k).
// `update` recomputes the time functions on the current modes (no sparse solve); `enrich` adds a
// rank-one pair for what the update leaves (a few sparse solves with the factorised K + Bᵀ k B).
#include "latin/global_stage.hpp"
#include "pgd/energy_modes.hpp"
#include "pgd/rank_one_enrichment.hpp"
#include "pgd/separated_loads.hpp"
#include "src/spacetime/interface_history.hpp"

namespace stc::pgd {

class SeparatedGlobalStage {
 public:
  /// Uses the operator and factor of `global` (which is not solved with: no m-solve here).
  SeparatedGlobalStage(const Problem& problem, const latin::GlobalStage& global);

  /// s from ŝ in span Υ: Ψ = Υᵀ F G + (BΥ)ᵀ W, W = λ̂ + k v̂;  v = BΥ Ψ,  λ = λ̂ − k (v − v̂).
  void update(const InterfaceHistory& hat, InterfaceHistory& s);

  /// A rank-one pair for the error the last update left, from the right-hand sides of that update.
  RankOnePair candidate(const EnrichmentOptions& options);
  /// Norm of the pair's change of s in the indicator's norm (docs/method.md §2): δv = BΥ ψ, δλ = −k δv.
  double interfaceNorm(const RankOnePair& pair) const;
  /// Appends the pair's space mode; false when it is already spanned.
  bool add(const RankOnePair& pair) { return modes_.add(pair.space); }
  /// Starts the modes from `vectors` (n_free × r, a neighbouring problem's modes: a warm start),
  /// A-orthonormalised in order, dependent ones dropped, at most `max_rank`. Returns the rank.
  int seed(const Eigen::MatrixXd& vectors, int max_rank);

  const EnergyModes& modes() const { return modes_; }
  long sparseSolves() const { return sparse_solves_; }

 private:
  const Problem& problem_;
  const latin::GlobalStage& global_;
  SeparatedLoads loads_;
  EnergyModes modes_;
  Eigen::MatrixXd W_;  ///< λ̂ + k v̂ of the last update
  long sparse_solves_ = 0;
};

}  // namespace stc::pgd
