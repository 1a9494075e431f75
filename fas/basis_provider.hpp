#pragma once
// Where the FAS coarse space comes from, cycle after cycle. A posteriori
// (fas/aposteriori/fixed_basis_provider.hpp): SVD modes of a converged solution, fixed, plus residual
// vectors renewed every cycle (seed §4.3). A priori (fas/apriori/apriori_basis.hpp): the energy SVD of
// the separated iterate built during the iterations.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "stcontact/fas/coarse_space.hpp"
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

}  // namespace stc::fas
