#include "src/contact/contact_state_table.hpp"

#include <algorithm>
#include <limits>

namespace stc {

ContactStateTable::ContactStateTable(const ContactInterface& contact, const InterfaceHistory& s)
    : s_(s), mu_(contact.friction) {
  force_scale_ = std::max(s.lambda.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
  length_scale_ = std::max(s.v.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
}

double ContactStateTable::slip(int i, int k) const {
  return s_.v(2 * i + 1, k) - (k > 0 ? s_.v(2 * i + 1, k - 1) : 0.0);
}

ContactState ContactStateTable::state(int i, int k) const {
  return classifyContact(s_.lambda(2 * i, k), s_.lambda(2 * i + 1, k), slip(i, k), mu_, force_scale_, length_scale_);
}

}  // namespace stc
