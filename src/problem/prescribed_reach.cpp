#include "stcontact/problem/prescribed_reach.hpp"

#include <algorithm>
#include <numeric>

#include "stcontact/mesh/connected_parts.hpp"

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

// Per node, how its body's translation enters the gaps: empty for one body; for two, +1 on the
// slave's body, −1 on the master's, 0 elsewhere (g = g0 + n · (w_s − w_m)). None when the slave or
// the master nodes lie on more than one body.
std::optional<std::vector<double>> bodySigns(const Problem& problem) {
  const ContactInterface& c = problem.contact;
  if (!c.isPair()) return std::vector<double>();
  const std::vector<int> part = partOfNodes(problem.body);
  const int slave = part[c.nodes.front()], master = part[c.master_nodes.front()];
  for (int i = 0; i < c.size(); ++i)
    if (part[c.nodes[i]] != slave || part[c.master_nodes[i]] != master) return std::nullopt;
  std::vector<double> sign(part.size(), 0.0);
  for (std::size_t node = 0; node < part.size(); ++node) sign[node] = part[node] == slave ? 1.0 : part[node] == master ? -1.0 : 0.0;
  return sign;
}

// The sign of the one body whose dofs `load` prescribes; none when it prescribes dofs of several.
std::optional<double> signOfLoad(const SeparatedLoad& load, const std::vector<double>& sign, int d) {
  std::optional<double> of;
  for (Eigen::Index dof = 0; dof < load.prescribed.size(); ++dof) {
    if (load.prescribed[dof] == 0.0) continue;
    const double s = sign[static_cast<std::size_t>(dof / d)];
    if (of && *of != s) return std::nullopt;
    of = s;
  }
  return of;
}

}  // namespace

std::optional<Eigen::MatrixXd> prescribedTranslation(const Problem& problem) {
  const int d = problem.dimension, m = problem.numSteps();
  const std::optional<std::vector<double>> sign = bodySigns(problem);
  if (!sign) return std::nullopt;
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(d, m);
  for (const SeparatedLoad& load : problem.loads) {
    if (allZero(load.values)) continue;
    const int axis = translationAxis(load, d);
    if (axis < 0) return std::nullopt;
    double s = 1.0;
    if (!sign->empty()) {  // two bodies: the part the history moves
      const std::optional<double> of = signOfLoad(load, *sign, d);
      if (!of) return std::nullopt;
      s = *of;
    }
    W.row(axis) += s * Eigen::Map<const Eigen::RowVectorXd>(load.values.data(), m);
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
  std::vector<int> every(static_cast<size_t>(contact.rows()));
  std::iota(every.begin(), every.end(), 0);
  return rigidMotionHistory(contact, W, every);
}

InterfaceHistory rigidMotionHistory(const ContactInterface& contact, const Eigen::MatrixXd& W, const std::vector<int>& rows) {
  const int d = contact.dimension;
  std::vector<char> held(static_cast<size_t>(contact.rows()), 0);
  for (int row : contact.held_rows) held[row] = 1;
  InterfaceHistory h = InterfaceHistory::zerosWithRows(static_cast<int>(rows.size()), static_cast<int>(W.cols()));
  for (size_t r = 0; r < rows.size(); ++r) {
    const int row = rows[r], i = row / d, a = row % d;
    if (held[row]) continue;
    h.v.row(r) = (a == 0 ? contact.normals.col(i) : contact.tangents.col((d - 1) * i + a - 1)).transpose() * W;
  }
  return h;
}

}  // namespace stc
