#include "stcontact/solver/contact_free_certificate.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace stc {
namespace {

constexpr double kRoundingRatio = 1e-12;  ///< forces and energy at rounding, relative to ‖v‖_k (2., 3.)
constexpr double kFlexibilityBound = 10.0;  ///< √c of 2.: ‖u − u0‖_K ≤ 10 ‖λ‖_{1/k}

/// ‖v‖²_k = Σ k v² over the rows (every row of node i has its k_i) and the instants.
double displacementNormSquared(const ContactInterface& c, const InterfaceHistory& s) {
  return (s.v.array().square().colwise() * c.search_direction.array()).sum();
}

/// ‖λ‖²_{1/k} = Σ λ² / k.
double forceNormSquared(const ContactInterface& c, const InterfaceHistory& s) {
  return (s.lambda.array().square().colwise() / c.search_direction.array()).sum();
}

/// The smallest gap g0_i + v_n(i, k) over the nodes and instants (+∞ without nodes), instant by
/// instant: v is stored by columns.
double smallestGap(const ContactInterface& c, const InterfaceHistory& s) {
  double smallest = INFINITY;
  for (Eigen::Index k = 0; k < s.v.cols(); ++k)
    for (int i = 0; i < c.size(); ++i) smallest = std::min(smallest, c.initial_gap[i] + s.v(c.normalRow(i), k));
  return smallest;
}

}  // namespace

bool storesNoStrainEnergy(const ContactInterface& contact, const InterfaceHistory& s, double energy) {
  return energy <= kRoundingRatio * displacementNormSquared(contact, s);
}

std::optional<std::string> contactFreeSolution(const ContactInterface& contact, const InterfaceHistory& s,
                                               double energy, double tolerance) {
  // The gap first: it reads the normal rows alone and rules out every contact problem once closed.
  const double gap = smallestGap(contact, s);
  if (!(gap > 0.0)) return std::nullopt;
  const double forces = std::sqrt(forceNormSquared(contact, s));
  const double displacements = std::sqrt(displacementNormSquared(contact, s));
  if (!(forces <= kRoundingRatio * displacements)) return std::nullopt;
  const bool rigid = storesNoStrainEnergy(contact, s, energy);
  if (!rigid && !(kFlexibilityBound * forces <= tolerance * std::sqrt(energy))) return std::nullopt;
  std::ostringstream reason;
  reason << "no contact at any instant: every gap stays open (smallest " << gap
         << ") and the contact forces are rounding (" << forces / displacements
         << " of the displacements, in the search direction's norms), so the iterate is the elastic solution "
            "without contact to rounding";
  if (rigid) reason << "; it stores no strain energy (a rigid motion), so no relative error is defined";
  return reason.str();
}

}  // namespace stc
