#include "src/problem/prescribed_reach.hpp"

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

std::optional<std::vector<int>> nodesWithinPrescribedReach(const Problem& problem, double margin) {
  const ContactInterface& contact = problem.contact;
  const int d = contact.dimension, m = problem.numSteps();
  // W(a, k): component a of the translation w(t_k).
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(d, m);
  for (const SeparatedLoad& load : problem.loads) {
    if (allZero(load.values)) continue;
    const int axis = translationAxis(load, d);
    if (axis < 0) return std::nullopt;
    W.row(axis) += Eigen::Map<const Eigen::RowVectorXd>(load.values.data(), m);
  }
  // Row i: n_i · w(t_k) over k.
  const Eigen::MatrixXd approach = contact.normals.transpose() * W;
  std::vector<int> nodes;
  for (int i = 0; i < contact.size(); ++i)
    if (contact.initial_gap[i] + approach.row(i).minCoeff() <= margin) nodes.push_back(i);
  return nodes;
}

}  // namespace stc
