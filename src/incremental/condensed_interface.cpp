#include "stcontact/incremental/condensed_interface.hpp"

#include "stcontact/incremental/lazy_delassus.hpp"

namespace stc {

CondensedInterface CondensedInterface::build(const Problem& problem, const SpdSolver& stiffness_free) {
  const auto& B = problem.contact.B;
  CondensedInterface c;
  const Eigen::MatrixXd Bt = Eigen::MatrixXd(B.transpose());
  c.delassus = symmetricDelassus(B, stiffness_free.solveOnThreads(Bt));
  c.free_response = freeInterfaceResponse(problem, stiffness_free);
  c.sparse_solves = static_cast<int>(Bt.cols() + problem.loads.size());
  return c;
}

Eigen::MatrixXd symmetricDelassus(const Eigen::SparseMatrix<double>& B, const Eigen::MatrixXd& responses) {
  const Eigen::MatrixXd W = B * responses;
  return 0.5 * (W + W.transpose());
}

void giveHeldRowsCompliance(const ContactInterface& contact, Eigen::MatrixXd& delassus) {
  const int d = contact.dimension;
  for (int r : contact.held_rows) delassus(r, r) = delassus(d * (r / d), d * (r / d));
}

}  // namespace stc
