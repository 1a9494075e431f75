#pragma once
// Space-time interface fields: one column per instant, rows 2i (normal) and 2i + 1 (tangential)
// of contact node i. These are the only quantities LATIN keeps between iterations (docs/method.md §2).
#include <Eigen/Core>

namespace stc {

struct InterfaceHistory {
  Eigen::MatrixXd v;       ///< interface displacements (v_n, v_t), 2n_C × m
  Eigen::MatrixXd lambda;  ///< contact forces on the body (λ_n, λ_t), 2n_C × m

  static InterfaceHistory zeros(int contact_nodes, int steps) {
    return {Eigen::MatrixXd::Zero(2 * contact_nodes, steps), Eigen::MatrixXd::Zero(2 * contact_nodes, steps)};
  }
  int numContactNodes() const { return static_cast<int>(v.rows() / 2); }
  int numSteps() const { return static_cast<int>(v.cols()); }
};

}  // namespace stc
