#include "stcontact/problem/prescribed_reach.hpp"

#include <algorithm>

namespace stc {
namespace {

bool allZero(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return v == 0.0; });
}

// The axis a (0 … d − 1) along which `load` prescribes every one of its dofs by the same unit amount,
// or −1 when it prescribes none or several axes.
int translationAxis(const SeparatedLoad& load, int d) {
  int axis = -1;
  for (Eigen::Index dof = 0; dof < load.prescribed.size(); ++dof) {
    const double p = load.prescribed[dof];
    if (p == 0.0) continue;
    const int a = static_cast<int>(dof % d);
    if (p != 1.0 || (axis >= 0 && a != axis)) return -1;
    axis = a;
  }
  return axis;
}

}  // namespace

std::optional<Eigen::MatrixXd> prescribedTranslation(const Problem& problem) {
  if (problem.contact.isPair()) return std::nullopt;  // what closes is the bodies' relative motion
  const int d = problem.dimension, m = problem.numSteps();
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(d, m);
  for (const SeparatedLoad& load : problem.loads) {
    if (allZero(load.values)) continue;
    const int axis = translationAxis(load, d);
    if (axis < 0) return std::nullopt;
    W.row(axis) += Eigen::Map<const Eigen::RowVectorXd>(load.values.data(), m);
  }
  return W;
}

std::vector<int> nodesWithinReach(const ContactInterface& contact, const Eigen::MatrixXd& W, double margin) {
  const Eigen::MatrixXd approach = contact.normals.transpose() * W;  // row i: n_i · w(t_k) over k
  std::vector<int> nodes;
  for (int i = 0; i < contact.size(); ++i)
    if (contact.initial_gap[i] + approach.row(i).minCoeff() <= margin) nodes.push_back(i);
  return nodes;
}

InterfaceHistory rigidMotionHistory(const ContactInterface& contact, const Eigen::MatrixXd& W) {
  const int d = contact.dimension;
  InterfaceHistory h = InterfaceHistory::zeros(contact, static_cast<int>(W.cols()));
  for (int i = 0; i < contact.size(); ++i) {
    h.v.row(contact.normalRow(i)) = contact.normals.col(i).transpose() * W;
    for (int a = 1; a < d; ++a)
      h.v.row(contact.normalRow(i) + a) = contact.tangents.col((d - 1) * i + a - 1).transpose() * W;
  }
  for (int row : contact.held_rows) h.v.row(row).setZero();
  return h;
}

}  // namespace stc
