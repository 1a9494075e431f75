#pragma once
// The true error of docs/method.md §2, measured against a reference solution on the same mesh and grid:
//   e² = Σ_k (u_k − u_ref,k)ᵀ K (u_k − u_ref,k) / Σ_k u_ref,kᵀ K u_ref,k
// with full displacements and the full stiffness. Any iterate that satisfies equilibrium
// K_ff u = f + Bᵀ λ (every LATIN global-stage result does) has u − u_ref = K_ff⁻¹ Bᵀ (λ − λ_ref) on the
// free dofs and zero on the prescribed ones, so the numerator is Σ_k δλ_kᵀ W δλ_k with the Delassus
// operator W = B K_ff⁻¹ Bᵀ: the error is measured on the interface alone.
//
// W is either given whole, or computed lazily (LazyDelassus): δλ is zero on the nodes where neither
// the iterate nor the reference carries a force, so Σ_k δλ_kᵀ W δλ_k needs W on the support S of δλ
// only, W_SS = the rows S of the columns S, d |S| sparse solves the first time a node enters S.
// In 3D the dense W is (3 n_C)² and costs 3 n_C solves (half_ball divisions 12: 5043 solves, 43 s);
// the lazy W of the same measure holds the nodes the iterates ever load, a few hundred.
#include <Eigen/Core>
#include <memory>
#include <mutex>

#include "stcontact/incremental/condensed_interface.hpp"
#include "stcontact/incremental/lazy_delassus.hpp"
#include "stcontact/solver/error_measure.hpp"

namespace stc {

class ErrorReference : public ErrorMeasure {
 public:
  /// `lambda_ref` (d n_C × m): the reference contact forces, e.g. from solveIncremental.
  ErrorReference(const Problem& problem, const SpdSolver& stiffness_free, Eigen::MatrixXd delassus,
                 Eigen::MatrixXd lambda_ref);
  /// The same with W computed lazily (header); keeps the factor and refers to `problem`, which must
  /// outlive it. relativeError may then be called from several threads (the columns are guarded).
  ErrorReference(const Problem& problem, std::shared_ptr<const SpdSolver> stiffness_free, Eigen::MatrixXd lambda_ref);
  ~ErrorReference() override;

  /// Relative energy error of an equilibrated iterate given by its contact forces; NaN when
  /// undefined (see defined()).
  double relativeError(const Eigen::MatrixXd& lambda) const override;
  /// False when the reference's strain energy is zero to round-off (a rigid motion without
  /// contact): the relative error is then 0/0, and its value would be noise (e.g. 1e3 for a
  /// correct iterate). Round-off: Σ uᵀKu has an absolute error up to γ_n Σ |u|ᵀ|K||u|,
  /// γ_n ≈ n ε (Higham, Accuracy and Stability, §3.1), n the number of dofs.
  bool defined() const override { return defined_; }
  /// Σ_k u_ref,kᵀ K u_ref,k (full field, full K).
  double referenceEnergy() const { return reference_energy_; }
  const Eigen::MatrixXd& referenceForces() const { return lambda_ref_; }
  /// Contact nodes whose Delassus columns the lazy measure has computed (0 with a whole W).
  int nodesComputed() const;

 private:
  void setReferenceEnergy(const Problem& problem, const SpdSolver& stiffness_free);
  double lazyEnergy(Eigen::MatrixXd d) const;  // Σ_k d_kᵀ W d_k on the support of d

  Eigen::MatrixXd delassus_;  // empty when lazy
  std::shared_ptr<const SpdSolver> factor_;
  std::unique_ptr<LazyDelassus> lazy_;
  const ContactInterface* contact_ = nullptr;
  mutable std::mutex lazy_mutex_;
  Eigen::MatrixXd lambda_ref_;
  double reference_energy_ = 0.0;
  bool defined_ = true;
};

/// Σ_k u_kᵀ K u_k for full displacements rebuilt from free ones (n_free × m).
double spaceTimeEnergy(const Problem& problem, const Eigen::MatrixXd& u_free);

}  // namespace stc
