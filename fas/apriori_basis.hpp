#pragma once
// The a priori coarse space of `fas-apriori` (docs/method.md §5): PGD spatial modes built
// during the iterations, plus residual vectors. Each cycle, the fine relaxation's displacement
// history ũ (n_free × m: the exact global stage, ũ_k = A⁻¹ r_k with r_k = f_k + Bᵀ(λ_k + k v_k)) is
// compared with the modes found so far; greedy rank-one enrichment (pgd/rank_one_enrichment.hpp,
// alternating fixed point with the space problem x = ũ ψᵀ and the time problem ψ_k = Υᵀ r_k) adds
// up to `modes_per_cycle` pairs for what the modes miss. The modes persist (up to `max_modes`);
// N_res residual vectors of what they still miss are renewed every cycle (seed §4.3).
// No SVD of a converged solution anywhere, and no product with A: r_k is known in separated form.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "fas/basis_provider.hpp"
#include "pgd/energy_modes.hpp"
#include "pgd/rank_one_enrichment.hpp"
#include "pgd/separated_loads.hpp"
#include "src/core/solver_settings.hpp"
#include "src/problem/problem.hpp"

namespace stc::fas {

struct AprioriBasisOptions {
  int residual_vectors = defaults::residual_vectors;    ///< N_res >= 0, renewed every cycle
  int modes_per_cycle = defaults::pgd_modes_per_cycle;  ///< rank-one pairs added per cycle at most, >= 1
  int max_modes = defaults::pgd_max_modes;              ///< PGD modes kept at most, >= 0 (then they stop growing)
  /// A warm start's seed (seed()) fills at most this share of `max_modes`, the leading seed modes;
  /// the rest is left to this problem's own enrichment. Warm relaxations over the seed scene's
  /// friction sweep 0.05:0.5:10 for shares 0, 0.25, 0.5, 0.75, 1: 176, 155, 147, 190, 245 (cold 272;
  /// docs/sweep.md, scene key solver.pgd_seed_share): a full seed leaves no room to adapt to the new
  /// value, an empty one throws the previous basis away. In [0, 1].
  double seed_share = defaults::pgd_seed_share;
  /// A pair is kept only if its energy norm is above this fraction of ũ's (nothing left below); >= 0.
  double relative_energy_drop = 1e-8;
  pgd::EnrichmentOptions enrichment;

  void validate() const;  ///< throws InputError naming the field, its value and the rule broken
};

class AprioriBasisProvider : public BasisProvider {
 public:
  /// `A` = K + Bᵀ k B (the global stage's operator). Validates `options` (InputError).
  AprioriBasisProvider(const Problem& problem, const Eigen::SparseMatrix<double>& A, AprioriBasisOptions options);
  /// Starts the modes from `vectors` (n_free × r, e.g. a neighbouring problem's modes, leading ones
  /// first: a warm start), A-orthonormalised in order, dependent ones dropped, at most
  /// seed_share · max_modes of them; enrichment goes on from there up to `max_modes`. Call before
  /// the solve. Returns the number of modes kept.
  int seed(const Eigen::MatrixXd& vectors);
  CoarseSpace coarseSpace(const Eigen::MatrixXd& u_tilde, const InterfaceHistory& s) override;
  const pgd::EnergyModes& modes() const { return modes_; }

 private:
  /// Adds pairs for what the modes miss of ũ; returns ũ's coordinates c_k = Υᵀ A ũ_k on the modes.
  Eigen::MatrixXd enrich(const Eigen::MatrixXd& u_tilde, const Eigen::MatrixXd& W);

  const Problem& problem_;
  const Eigen::SparseMatrix<double>& A_;
  AprioriBasisOptions options_;
  pgd::SeparatedLoads loads_;
  pgd::EnergyModes modes_;
};

}  // namespace stc::fas
