#pragma once
// Space-time interface fields: one column per instant; contact node i owns the d rows from d i on
// (normal, then the d − 1 tangential components; d = ContactInterface::dimension). These are the
// only quantities LATIN keeps between iterations (docs/method.md §2).
#include <Eigen/Core>

#include "stcontact/contact/contact_interface.hpp"

namespace stc {

struct InterfaceHistory {
  Eigen::MatrixXd v;       ///< interface displacements (v_n, v_t), d n_C × m
  Eigen::MatrixXd lambda;  ///< contact forces on the body (λ_n, λ_t), d n_C × m

  /// Zero fields for `contact` on `steps` instants.
  static InterfaceHistory zeros(const ContactInterface& contact, int steps) { return zerosWithRows(contact.rows(), steps); }
  static InterfaceHistory zerosWithRows(int rows, int steps) {
    return {Eigen::MatrixXd::Zero(rows, steps), Eigen::MatrixXd::Zero(rows, steps)};
  }
  int numSteps() const { return static_cast<int>(v.cols()); }
};

}  // namespace stc
