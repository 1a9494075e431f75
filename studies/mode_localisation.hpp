#pragma once
// How localised at the contact zone a spatial mode is: the numbers behind the seed's observation
// (§3.2, Fig. 2) "the first three space modes are global (structure scale), the higher ones are
// localised at the contact zone; after the sixth, their length is that of the mesh".
//
// Measure. The energy of a field Υ splits over the elements, ΥᵀKΥ = Σ_e E_e with
// E_e = A_e (B_e Υ_e)ᵀ D (B_e Υ_e) (P1 elasticity, src/fem/elasticity.hpp). With d_e the distance
// from the centroid of element e to the contact zone Γ_c (below), a mode's
//   band share   s(d) = Σ_{e: d_e ≤ d} E_e / Σ_e E_e                 (share of its energy near contact)
//   mean depth   ⟨d⟩ = Σ_e E_e d_e / Σ_e E_e                          (its length scale away from contact)
// and the band's area share a(d) = Σ_{d_e ≤ d} A_e / Σ_e A_e, the share a uniform energy density
// would put there; s(d)/a(d) > 1 is concentration at the contact.
//
// Contact zone Γ_c: the potential contact nodes that are closed (not open) at some instant of the
// solution, and the boundary edges joining two of them; for the seed scene the arc segment
// x ∈ [−0.30, 0.30] (21 nodes at t_200). Choice and alternatives (docs/svd_seed.md): a band around
// the zone that actually carries contact forces, rather than a disc around the lowest point, follows
// the zone as it widens and slides; the bands used, d = 0.05 R, 0.1 R and 0.2 R, are about 1.5, 3 and
// 6 element sizes at the arc (h = πR/102 ≈ 0.031 R) and 1/6, 1/3 and 2/3 of the final contact
// half-width a ≈ 0.30 R, the depth over which Hertz-like contact stresses decay.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_result.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc {

/// The potential contact nodes closed at some instant, and the boundary edges between two of them.
struct ContactZone {
  std::vector<int> nodes;                  ///< mesh node ids, increasing
  std::vector<std::array<int, 2>> edges;   ///< boundary edges with both ends in `nodes`
  double xmin = 0.0, xmax = 0.0;           ///< extent of the nodes along x (initial positions)

  bool empty() const { return nodes.empty(); }
  /// Closed means "not open" in the classification of the output writers (ContactStateTable on the
  /// contact-admissible history).
  static ContactZone everClosed(const Problem& problem, const SolveResult& result);
};

/// One mode's localisation numbers (see the header comment).
struct LocalisationMeasure {
  std::vector<double> band_share;  ///< s(d) for each band depth
  double mean_distance = 0.0;      ///< ⟨d⟩
  double energy = 0.0;             ///< Σ_e E_e = ΥᵀKΥ (1 for an energy-orthonormal mode)
};

class ModeLocalisation {
 public:
  /// Precomputes per element B_e, A_e and d_e. Throws InputError if the zone is empty or a depth is
  /// not positive and finite.
  ModeLocalisation(const Problem& problem, ContactZone zone, std::vector<double> band_depths);

  /// The measure of one full-field vector (n = 2 × nodes).
  LocalisationMeasure measure(const Eigen::VectorXd& mode) const;
  /// E_e for every element.
  Eigen::VectorXd elementEnergies(const Eigen::VectorXd& u) const;

  const Eigen::VectorXd& distances() const { return distance_; }  ///< d_e
  const Eigen::VectorXd& areas() const { return area_; }          ///< A_e
  std::vector<double> bandAreaShares() const;                      ///< a(d) for each depth
  const std::vector<double>& bandDepths() const { return depths_; }
  const ContactZone& zone() const { return zone_; }

 private:
  Eigen::Matrix3Xi triangles_;  ///< a copy: the object does not depend on the Problem's lifetime
  int dofs_ = 0;
  Eigen::Matrix3d hooke_;
  std::vector<Eigen::Matrix<double, 3, 6>> strain_;  ///< B_e
  Eigen::VectorXd area_, distance_;
  ContactZone zone_;
  std::vector<double> depths_;
};

}  // namespace stc
