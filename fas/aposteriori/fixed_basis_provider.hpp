#pragma once
// The a posteriori coarse space on LATIN's fine level (seed §4.3): fixed vectors, the SVD modes of a
// converged solution restricted to the free dofs, plus residual vectors of the last global stage's
// displacement history (fas/residual_vectors.hpp), renewed every cycle.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "stcontact/fas/basis_provider.hpp"
#include "stcontact/latin/global_stage.hpp"

namespace stc::fas {

/// Fixed vectors (e.g. SVD modes restricted to the free dofs) + N_res residual vectors of the
/// displacement history ũ of `global`'s last solve (which must keep it: keepDisplacements).
class FixedBasisProvider : public BasisProvider {
 public:
  FixedBasisProvider(const Eigen::MatrixXd& vectors, int residual_vectors, const latin::GlobalStage& global,
                     const Eigen::SparseMatrix<double>& B);
  CoarseSpace coarseSpace(const InterfaceHistory& hat) override;
  const CoarseSpace& fixedSpace() const { return fixed_; }

 private:
  CoarseSpace fixed_;
  int residual_vectors_;
  const latin::GlobalStage& global_;
  const Eigen::SparseMatrix<double>& B_;
};

}  // namespace stc::fas
