#pragma once
// Open/stick/slip of every contact node and instant of an interface history (classifyContact of
// contact_state.hpp, docs/method.md §1), for the output tables and the mode localisation report.
#include "stcontact/contact/contact_interface.hpp"
#include "stcontact/contact/contact_state.hpp"
#include "stcontact/spacetime/interface_history.hpp"

#include <utility>
#include <vector>

namespace stc {

/// Open/stick/slip of every node and instant of a history (classifyContact with the history's
/// largest |λ| and |v| as scales). Use the contact-admissible iterate (SolveResult::contactStates).
class ContactStateTable {
 public:
  ContactStateTable(const ContactInterface& contact, const InterfaceHistory& s);
  /// The states of `whole` with the nodes `part_nodes` read from `part` instead (d rows per node, in
  /// that order): an iterate held on a contact zone alone, the same as `whole` elsewhere
  /// (SolveResult::admissible_nodes). The scales are those of the history so patched.
  ContactStateTable(const ContactInterface& contact, const InterfaceHistory& whole, const InterfaceHistory& part,
                    const std::vector<int>& part_nodes);
  /// Δv_t = v_t(t_k) − v_t(t_{k−1}), with v_t(t_{−1}) = 0 (2D); its norm |Δv_t| in 3D. The state
  /// uses λ_t in 2D and |λ_t| in 3D.
  double slip(int i, int k) const;
  ContactState state(int i, int k) const;

 private:
  // The history that holds node i, and the row of its normal component there.
  std::pair<const InterfaceHistory*, int> source(int i) const;

  const InterfaceHistory& whole_;
  const InterfaceHistory* part_ = nullptr;
  std::vector<int> part_index_;  ///< per node: its index in part_nodes, −1 when read from whole_
  int d_;
  double mu_, force_scale_, length_scale_;
};

}  // namespace stc
