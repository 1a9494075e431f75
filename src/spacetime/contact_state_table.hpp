#pragma once
// Open/stick/slip of every contact node and instant of an interface history (classifyContact of
// contact_state.hpp, docs/method.md §1), for the output tables and the mode localisation report.
#include "stcontact/contact/contact_interface.hpp"
#include "stcontact/contact/contact_state.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc {

/// Open/stick/slip of every node and instant of a history (classifyContact with the history's
/// largest |λ| and |v| as scales). Use the contact-admissible iterate (SolveResult::admissible()).
class ContactStateTable {
 public:
  ContactStateTable(const ContactInterface& contact, const InterfaceHistory& s);
  /// Δv_t = v_t(t_k) − v_t(t_{k−1}), with v_t(t_{−1}) = 0 (2D); its norm |Δv_t| in 3D. The state
  /// uses λ_t in 2D and |λ_t| in 3D.
  double slip(int i, int k) const;
  ContactState state(int i, int k) const;

 private:
  const InterfaceHistory& s_;
  int d_;
  double mu_, force_scale_, length_scale_;
};

}  // namespace stc
