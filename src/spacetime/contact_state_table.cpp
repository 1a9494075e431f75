#include "stcontact/spacetime/contact_state_table.hpp"

#include <algorithm>
#include <limits>

namespace stc {

ContactStateTable::ContactStateTable(const ContactInterface& contact, const InterfaceHistory& s)
    : s_(s), d_(contact.dimension), mu_(contact.friction) {
  force_scale_ = std::max(s.lambda.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
  length_scale_ = std::max(s.v.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
}

double ContactStateTable::slip(int i, int k) const {
  const int t = d_ * i + 1;
  if (d_ == 2) return s_.v(t, k) - (k > 0 ? s_.v(t, k - 1) : 0.0);
  const Eigen::Vector2d now = s_.v.col(k).segment<2>(t);
  return k > 0 ? (now - s_.v.col(k - 1).segment<2>(t)).norm() : now.norm();
}

ContactState ContactStateTable::state(int i, int k) const {
  const int n = d_ * i;
  const double lt = d_ == 2 ? s_.lambda(n + 1, k) : s_.lambda.col(k).segment(n + 1, d_ - 1).norm();
  return classifyContact(s_.lambda(n, k), lt, slip(i, k), mu_, force_scale_, length_scale_);
}

}  // namespace stc
