#pragma once
// Where the FAS coarse space comes from, cycle after cycle. A posteriori: SVD modes of a converged
// solution, fixed, plus residual vectors renewed every cycle (seed §4.3). A priori
// (fas/apriori/apriori_basis.hpp): the energy SVD of the separated iterate built during the iterations.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "stcontact/fas/coarse_space.hpp"
#include "stcontact/latin/global_stage.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc::fas {

class BasisProvider {
 public:
  virtual ~BasisProvider() = default;
  /// The coarse space for the coming coarse step, given the local-stage iterate ŝ = `hat` of the
  /// fine level, from which its next global stage starts (the a priori provider projects that
  /// stage's right-hand side; a provider reads the displacement history of the last global stage,
  /// when it needs one, from the global stage it was built on).
  virtual CoarseSpace coarseSpace(const InterfaceHistory& hat) = 0;
  /// True when the coarse space comes from the anticipated expansion (fas/apriori/apriori_basis.hpp): its
  /// corrections are judged with defaults::safeguardGrowth(dimension, true) unless θ is set.
  virtual bool anticipates() const { return false; }
};

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
