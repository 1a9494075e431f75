#pragma once
// A solver's output: the interface histories (full fields are rebuilt from them on demand,
// see condensed_interface.hpp) and the summary.
#include <optional>
#include <vector>

#include "stcontact/solver/solve_summary.hpp"
#include "stcontact/spacetime/contact_state_table.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc {

/// A displacement history in separated form: u_free(t_k) = modes · time.col(k) (n_free × r modes,
/// r × m time functions), what a space-time strategy holds of its solution.
struct SeparatedDisplacement {
  bool held = false;     ///< false: the strategy did not hand one (the writer then solves from λ)
  Eigen::MatrixXd modes;  ///< n_free × r
  Eigen::MatrixXd time;   ///< r × m
  Eigen::VectorXd at(Eigen::Index k) const { return modes * time.col(k); }  ///< u_free(t_k)
};

struct SolveResult {
  InterfaceHistory interface;  ///< the solution: for LATIN the last global-stage (equilibrated) iterate
  SolveSummary summary;
  /// The last iterate that satisfies the contact law exactly (LATIN's last local stage ŝ), when it
  /// differs from `interface`; the writers classify open/stick/slip from it (contactStates). Held
  /// on the nodes `admissible_nodes` alone when they are given (d rows per node, in that order), the
  /// same as `interface` on the others: a solve on a contact zone (fas/apriori/zone_rounds.hpp).
  std::optional<InterfaceHistory> contact_admissible;
  std::vector<int> admissible_nodes;  ///< empty: contact_admissible holds every node
  /// The spatial modes of the basis the strategy built a priori (fas-apriori, latin-pgd): n_free × r,
  /// orthonormal in the energy product of this problem's K + Bᵀ k B; empty for the others. A solve of
  /// a neighbouring problem may start its basis from them (SolveInputs::basis_seed).
  Eigen::MatrixXd spatial_modes;
  /// The interface directions of a separated global stage (fas-apriori, latin-pgd; d n_C × p,
  /// pgd/response_basis.hpp); empty for the others. A solve of a neighbouring problem may start its
  /// directions from them (SolveInputs::basis_seed): a warm start.
  Eigen::MatrixXd interface_directions;
  /// The free dofs' displacement history the strategy holds (fas-apriori, latin-pgd, when asked:
  /// SolveInputs::separated_displacement), truncated in energy within the tolerance's slack; not
  /// held by the others. The writer forms its frames from it without a solve.
  SeparatedDisplacement displacement;

  /// Open/stick/slip of every node and instant, from the contact-admissible iterate (the table reads
  /// this result's histories: it lives no longer than the result).
  ContactStateTable contactStates(const ContactInterface& contact) const;
  /// The contact-admissible iterate on every node (`interface` when there is none): a copy, for
  /// checks; takeAdmissible moves it out.
  InterfaceHistory admissible() const;
  InterfaceHistory takeAdmissible() &&;
};

}  // namespace stc
