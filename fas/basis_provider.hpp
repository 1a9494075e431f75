#pragma once
// Where the FAS coarse space comes from, cycle after cycle. A posteriori (docs/method.md §4): SVD modes of a
// converged solution, fixed, plus residual vectors renewed every cycle (seed §4.3). A priori
// (docs/method.md §5): PGD modes built during the iterations, plus residual vectors.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "fas/coarse_space.hpp"
#include "src/spacetime/interface_history.hpp"

namespace stc::fas {

class BasisProvider {
 public:
  virtual ~BasisProvider() = default;
  /// The coarse space for the coming coarse step, given the current displacement history ũ
  /// (n_free × m) and interface history s = (v, λ) of the last global stage (so A ũ_k = f_k +
  /// Bᵀ(λ_k + k v_k) is known without a product with A).
  virtual CoarseSpace coarseSpace(const Eigen::MatrixXd& u_tilde, const InterfaceHistory& s) = 0;
};

/// Fixed vectors (e.g. SVD modes restricted to the free dofs) + N_res residual vectors.
class FixedBasisProvider : public BasisProvider {
 public:
  FixedBasisProvider(const Eigen::MatrixXd& vectors, int residual_vectors, const Eigen::SparseMatrix<double>& A,
                     const Eigen::SparseMatrix<double>& B);
  CoarseSpace coarseSpace(const Eigen::MatrixXd& u_tilde, const InterfaceHistory& s) override;
  const CoarseSpace& fixedSpace() const { return fixed_; }

 private:
  CoarseSpace fixed_;
  int residual_vectors_;
  const Eigen::SparseMatrix<double>& A_;
  const Eigen::SparseMatrix<double>& B_;
};

}  // namespace stc::fas
