#pragma once
// The responses of the global-stage operator A = K_ff + Bᵀ k B that the separated global stage
// reuses (docs/method.md §5, "Separated global stage"). The global stage's right-hand sides are
//   r_k = F g_k + Bᵀ w_k,   w_k = λ̂_k + k v̂_k   (loads in separated form, Problem::loads),
// so its solutions are u_k = U_F g_k + A⁻¹ Bᵀ w_k with the load responses U_F = A⁻¹ F (q solves,
// once). For the interface part the basis keeps directions Z = [z_1 … z_p] (2n_C × p, orthonormal
// in the k⁻¹ product: Zᵀ k⁻¹ Z = I), their responses X = A⁻¹ Bᵀ Z (n_free × p: the spatial modes
// of the separated displacement u_k ≈ U_F g_k + X c_k) and their traces T = B X (2n_C × p).
// Nothing here is n_free × m: memory O((q + p) n_free + (q + p + m) n_C).
#include <Eigen/Core>

#include "src/linalg/spd_factor.hpp"
#include "src/problem/problem.hpp"

namespace stc::pgd {

class ResponseBasis {
 public:
  /// `factor` factorises A = K_ff + Bᵀ k B, k = problem.contact.search_direction.
  ResponseBasis(const Problem& problem, const SpdFactor& factor);

  int size() const { return static_cast<int>(Z_.cols()); }       ///< p
  int maxSize() const { return static_cast<int>(Z_.rows()); }    ///< 2n_C: Z then spans every w
  const Eigen::MatrixXd& directions() const { return Z_; }       ///< Z, 2n_C × p
  const Eigen::MatrixXd& scaledDirections() const { return Zs_; } ///< k^{-1/2} Z: orthonormal columns
  const Eigen::MatrixXd& responses() const { return X_; }        ///< X = A⁻¹ Bᵀ Z, n_free × p
  const Eigen::MatrixXd& traces() const { return T_; }           ///< T = B X, 2n_C × p
  const Eigen::MatrixXd& loadResponses() const { return UF_; }   ///< U_F = A⁻¹ F, n_free × q
  const Eigen::MatrixXd& loadTraces() const { return VF_; }      ///< V_F = B U_F, 2n_C × q
  const Eigen::MatrixXd& loadEnergy() const { return UFtF_; }    ///< U_Fᵀ F = U_Fᵀ A U_F, q × q
  const Eigen::MatrixXd& loadHistories() const { return G_; }    ///< G, q × m
  const Eigen::MatrixXd& freeResponse() const { return v0_; }    ///< V_F G: v of w = 0, 2n_C × m
  /// √k and 1/√k per interface row: the k⁻¹ product is the Euclidean one of k^{-1/2} w.
  const Eigen::VectorXd& sqrtK() const { return sqrt_k_; }
  const Eigen::VectorXd& invSqrtK() const { return inv_sqrt_k_; }

  /// Appends the columns of `candidates` (2n_C × b), k⁻¹-orthogonalised against the directions and
  /// each other (Gram–Schmidt, twice), dropping those left with less than `drop` of their norm, and
  /// solves for their responses (one multi-right-hand-side solve). Returns the number appended.
  int append(const Eigen::MatrixXd& candidates, double drop = 1e-8);
  /// Right-hand sides solved so far (loads included).
  long sparseSolves() const { return sparse_solves_; }

 private:
  const Problem& problem_;
  const SpdFactor& factor_;
  Eigen::VectorXd sqrt_k_, inv_sqrt_k_;
  Eigen::MatrixXd Z_, Zs_, X_, T_, UF_, VF_, UFtF_, G_, v0_;
  long sparse_solves_ = 0;
};

}  // namespace stc::pgd
