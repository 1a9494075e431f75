#include "src/solver/error_reference.hpp"

#include <cmath>

namespace stc {

double spaceTimeEnergy(const Problem& problem, const Eigen::MatrixXd& u_free) {
  double energy = 0.0;
  for (int k = 0; k < problem.numSteps(); ++k) {
    const Eigen::VectorXd u = problem.fullDisplacement(u_free.col(k), k);
    energy += u.dot(problem.stiffness * u);
  }
  return energy;
}

ErrorReference::ErrorReference(const Problem& problem, const SpdFactor& stiffness_free, Eigen::MatrixXd delassus,
                               Eigen::MatrixXd lambda_ref)
    : delassus_(std::move(delassus)), lambda_ref_(std::move(lambda_ref)) {
  reference_energy_ = spaceTimeEnergy(problem, displacementsFromForces(problem, stiffness_free, lambda_ref_));
}

double ErrorReference::relativeError(const Eigen::MatrixXd& lambda) const {
  const Eigen::MatrixXd d = lambda - lambda_ref_;
  const double numerator = (d.cwiseProduct(delassus_ * d)).sum();
  if (reference_energy_ <= 0.0) return std::sqrt(std::max(numerator, 0.0));
  return std::sqrt(std::max(numerator, 0.0) / reference_energy_);
}

}  // namespace stc
