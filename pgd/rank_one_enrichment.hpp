#pragma once
// The global stage of LATIN in separated form (docs/method.md §5). Its right-hand sides are
//   r_k = F g_k + Bᵀ w_k,   w_k = λ̂(t_k) + k v̂(t_k),
// with F the separated load vectors and g_k their values at t_k (Problem::loads).
// Update: with Υ A-orthonormal, the Galerkin solution in span Υ has time functions
//   Ψ = Υᵀ F G + (B Υ)ᵀ W                                   (r × m, no sparse solve).
// Enrichment: a rank-one pair (Υ, ψ) for the Galerkin error e_k = A⁻¹ r_k − Υ Ψ_k, by the
// alternating fixed point of progressive Galerkin PGD (Ladevèze 1999; Nouy 2010, "A priori model
// reduction through PGD", alg. 1):
//   space:  Υ ← (I − Υ Υᵀ A) A⁻¹ Σ_k ψ_k r_k, A-normalised    (one sparse solve)
//   time:   ψ_k ← Υᵀ r_k = (Υᵀ F) g_k + (B Υ)ᵀ w_k            (Υ A-orthogonal to the modes)
// (the projection removes Υ Ψ ψᵀ, the modes' part, so the pair approximates e, not A⁻¹ r).
#include <Eigen/Core>
#include <functional>

#include "pgd/energy_modes.hpp"

namespace stc::pgd {

/// Time functions of the Galerkin solution in span Υ: Ψ = Υᵀ F G + (B Υ)ᵀ W.
Eigen::MatrixXd updateTimeFunctions(const EnergyModes& modes, const Eigen::MatrixXd& G, const Eigen::MatrixXd& W);

/// The space problem of one sweep: x = A⁻¹ Σ_k ψ_k r_k for a time function ψ (1 × m). One sparse
/// solve in `latin-pgd`; a product with the known solutions A⁻¹ r_k in `fas-apriori`.
using SpaceProblem = std::function<Eigen::VectorXd(const Eigen::RowVectorXd& psi)>;
/// The time problem of one sweep: ψ_k = Υᵀ r_k for every k, for a space mode Υ.
using TimeProblem = std::function<Eigen::RowVectorXd(const Eigen::VectorXd& space)>;

/// The time problem for right-hand sides given in separated form: ψ = (Υᵀ F) G + (B Υ)ᵀ W.
TimeProblem separatedTimeProblem(const EnergyModes& modes, const Eigen::MatrixXd& G, const Eigen::MatrixXd& W);

struct EnrichmentOptions {
  int max_sweeps = 4;         ///< alternating fixed-point sweeps (each one space problem)
  double sweep_tolerance = 1e-2;  ///< stop when ‖ψ − ψ_prev‖ ≤ tol ‖ψ‖ (ψ for an A-normalised Υ)
};

struct RankOnePair {
  Eigen::VectorXd space;      ///< Υ, A-normalised and A-orthogonal to the modes (empty: nothing left)
  Eigen::RowVectorXd time;    ///< ψ (1 × m): ‖ψ‖ is the energy norm of the pair Υ ψ
  int space_problems = 0;     ///< sparse solves (or products) spent
};

/// One rank-one pair for the Galerkin error that `modes` leave of the solutions A⁻¹ r_k, starting
/// the fixed point from the time function `psi0`.
RankOnePair enrichRankOne(const EnergyModes& modes, const SpaceProblem& space_problem,
                          const TimeProblem& time_problem, Eigen::RowVectorXd psi0,
                          const EnrichmentOptions& options = {});

}  // namespace stc::pgd
