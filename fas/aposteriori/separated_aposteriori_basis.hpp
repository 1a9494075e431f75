#pragma once
// The seed's a posteriori coarse space (§4.3: SVD modes of a converged solution + N_res residual
// vectors renewed every cycle) on the separated fine level of `fas-apriori` (pgd/controlled_global_stage.hpp),
// so that the two bases can be compared on the same fine level (docs/compare_bases.md, "Like for like").
// The residual vectors span what the fixed modes Y (A-orthonormal) miss of the last global stage's
// displacement history ũ = Φ Θ, Φ = [U_F X] (pgd/separated_history.hpp):
//   R = ũ − Y (Yᵀ A ũ),
// found from small factors, without an n_free × m array. With Φ̂ = Φ R_K⁻¹ (A-orthonormal, the energy
// factor) and S = Φ̂ᵀ A Y (EnergyFactor::projections of Φᵀ A Y = [U_Fᵀ A Y; Zᵀ B Y], as A X = Bᵀ Z),
// Y = Φ̂ S + Y⊥ with Y⊥ᵀ A Y⊥ = I − SᵀS = V D Vᵀ; Ŷ⊥ = Y⊥ V D^{-1/2} completes Φ̂ to an A-orthonormal
// basis of span[Φ, Y], in which
//   ũ = [Θ̂; 0],   Y = Γ = [S; D^{1/2} Vᵀ],   R = [Θ̂; 0] − Γ (Sᵀ Θ̂)   (Θ̂ = R_K Θ),
// and the N_res leading left singular vectors of that (s' + k') × m matrix are the residual vectors,
// A-orthogonal to Y. Their traces are B Φ̂ U_top + (B Y − B Φ̂ S) V D^{-1/2} U_bottom.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "stcontact/fas/basis_provider.hpp"
#include "stcontact/pgd/controlled_global_stage.hpp"

namespace stc::fas {

class SeparatedAposterioriProvider : public BasisProvider {
 public:
  /// `modes`: fixed vectors on the free dofs (e.g. aposterioriModes), A-orthonormalised here with
  /// the stage's A = K_ff + Bᵀ k B; `B`: the interface of the stage's problem.
  SeparatedAposterioriProvider(const Eigen::MatrixXd& modes, int residual_vectors,
                               const pgd::ControlledGlobalStage& stage, const Eigen::SparseMatrix<double>& B);
  CoarseSpace coarseSpace(const InterfaceHistory& hat) override;

 private:
  /// The traces of the N_res residual vectors of the last global stage's history (the header's R).
  Eigen::MatrixXd residualTraces() const;

  const pgd::ControlledGlobalStage& stage_;
  CoarseSpace fixed_;
  Eigen::MatrixXd AY_;  ///< A Y of the A-orthonormal fixed modes
  int residual_vectors_;
};

}  // namespace stc::fas
