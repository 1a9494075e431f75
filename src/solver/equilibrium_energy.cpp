#include "stcontact/solver/equilibrium_energy.hpp"

#include "stcontact/linalg/dense_product.hpp"

namespace stc {

EquilibriumEnergy::EquilibriumEnergy(const Problem& problem, const SpdSolver& search_factor) : problem_(problem) {
  const int q = static_cast<int>(problem.loads.size()), n = problem.numFreeDofs(), m = problem.numSteps();
  Eigen::MatrixXd F(n, q), P(problem.numDofs(), q);
  histories_.resize(q, m);
  for (int j = 0; j < q; ++j) {
    F.col(j) = problem.loads[j].free_force;
    P.col(j) = problem.loads[j].prescribed;
    histories_.row(j) = Eigen::Map<const Eigen::RowVectorXd>(problem.loads[j].values.data(), m);
  }
  const Eigen::MatrixXd KP = problem.stiffness * P;  // full field; its free rows are D = K_fP P
  Eigen::MatrixXd D(n, q);
  for (int i = 0; i < n; ++i) D.row(i) = KP.row(problem.free_dofs[i]);
  prescribed_energy_ = P.transpose() * KP;
  load_vectors_.resize(n, 2 * q);
  load_vectors_ << F, D;
  const Eigen::MatrixXd responses = search_factor.solve(load_vectors_);
  load_responses_ = responses.transpose() * F;
  interface_traces_ = problem.contact.B * responses;
}

double EquilibriumEnergy::operator()(const InterfaceHistory& s) const {
  const int q = static_cast<int>(histories_.rows());
  // Projections of u_k on the columns of [F D]: (A⁻¹a)ᵀ F g_k + (B A⁻¹ a)ᵀ w_k, w_k = λ_k + k v_k
  // taken as two products (no rows × m temporary; linalg's, on the threads).
  const Eigen::MatrixXd scaled_traces = problem_.contact.search_direction.asDiagonal() * interface_traces_;
  Eigen::MatrixXd projections, of_v;
  linalg::multiplyTransposed(interface_traces_, s.lambda, projections);
  linalg::multiplyTransposed(scaled_traces, s.v, of_v);
  projections += of_v;
  projections.noalias() += load_responses_ * histories_;
  double energy = s.v.cwiseProduct(s.lambda).sum();
  if (q > 0) {
    energy += projections.topRows(q).cwiseProduct(histories_).sum();
    energy += 2.0 * projections.bottomRows(q).cwiseProduct(histories_).sum();
    energy += histories_.cwiseProduct(prescribed_energy_ * histories_).sum();
  }
  return energy;
}

}  // namespace stc
