#include "stcontact/spacetime/contact_state_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stc {

namespace {

double atLeastTiny(double x) { return std::max(x, std::numeric_limits<double>::min()); }

// max |a(r, k)| over the rows r with keep[r], column by column (contiguous in a column-major array).
double maxAbsOnRows(const Eigen::MatrixXd& a, const std::vector<char>& keep) {
  double m = 0.0;
  for (Eigen::Index k = 0; k < a.cols(); ++k)
    for (Eigen::Index r = 0; r < a.rows(); ++r)
      if (keep[r]) m = std::max(m, std::abs(a(r, k)));
  return m;
}

}  // namespace

ContactStateTable::ContactStateTable(const ContactInterface& contact, const InterfaceHistory& s)
    : whole_(s), d_(contact.dimension), mu_(contact.friction) {
  force_scale_ = atLeastTiny(s.lambda.cwiseAbs().maxCoeff());
  length_scale_ = atLeastTiny(s.v.cwiseAbs().maxCoeff());
}

ContactStateTable::ContactStateTable(const ContactInterface& contact, const InterfaceHistory& whole,
                                     const InterfaceHistory& part, const std::vector<int>& part_nodes)
    : whole_(whole), part_(&part), part_index_(contact.size(), -1), d_(contact.dimension), mu_(contact.friction) {
  std::vector<char> off_part(whole.v.rows(), 1);
  for (int row : rowsOfNodes(d_, part_nodes)) off_part[row] = 0;
  for (size_t j = 0; j < part_nodes.size(); ++j) part_index_[part_nodes[j]] = static_cast<int>(j);
  const auto largest = [](const Eigen::MatrixXd& a) { return a.size() ? a.cwiseAbs().maxCoeff() : 0.0; };
  force_scale_ = atLeastTiny(std::max(largest(part.lambda), maxAbsOnRows(whole.lambda, off_part)));
  length_scale_ = atLeastTiny(std::max(largest(part.v), maxAbsOnRows(whole.v, off_part)));
}

std::pair<const InterfaceHistory*, int> ContactStateTable::source(int i) const {
  if (part_ && part_index_[i] >= 0) return {part_, d_ * part_index_[i]};
  return {&whole_, d_ * i};
}

double ContactStateTable::slip(int i, int k) const {
  const auto [s, n] = source(i);
  const int t = n + 1;
  if (d_ == 2) return s->v(t, k) - (k > 0 ? s->v(t, k - 1) : 0.0);
  const Eigen::Vector2d now = s->v.col(k).segment<2>(t);
  return k > 0 ? (now - s->v.col(k - 1).segment<2>(t)).norm() : now.norm();
}

ContactState ContactStateTable::state(int i, int k) const {
  const auto [s, n] = source(i);
  const double lt = d_ == 2 ? s->lambda(n + 1, k) : s->lambda.col(k).segment(n + 1, d_ - 1).norm();
  return classifyContact(s->lambda(n, k), lt, slip(i, k), mu_, force_scale_, length_scale_);
}

}  // namespace stc
