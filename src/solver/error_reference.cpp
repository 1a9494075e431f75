#include "src/solver/error_reference.hpp"

#include <cmath>
#include <limits>

namespace stc {

double spaceTimeEnergy(const Problem& problem, const Eigen::MatrixXd& u_free) {
  double energy = 0.0;
  for (int k = 0; k < problem.numSteps(); ++k) {
    const Eigen::VectorXd u = problem.fullDisplacement(u_free.col(k), k);
    energy += u.dot(problem.stiffness * u);
  }
  return energy;
}

namespace {

/// Σ_k |u_k|ᵀ |K| |u_k|: the size of the terms that Σ_k u_kᵀ K u_k adds up (its round-off scale).
double absoluteEnergyScale(const Problem& problem, const Eigen::MatrixXd& u_free) {
  const Eigen::SparseMatrix<double> absK = problem.stiffness.cwiseAbs();
  double scale = 0.0;
  for (int k = 0; k < problem.numSteps(); ++k) {
    const Eigen::VectorXd u = problem.fullDisplacement(u_free.col(k), k).cwiseAbs();
    scale += u.dot(absK * u);
  }
  return scale;
}

}  // namespace

ErrorReference::ErrorReference(const Problem& problem, const SpdFactor& stiffness_free, Eigen::MatrixXd delassus,
                               Eigen::MatrixXd lambda_ref)
    : delassus_(std::move(delassus)), lambda_ref_(std::move(lambda_ref)) {
  const Eigen::MatrixXd u_free = displacementsFromForces(problem, stiffness_free, lambda_ref_);
  reference_energy_ = spaceTimeEnergy(problem, u_free);
  const double gamma = problem.numDofs() * std::numeric_limits<double>::epsilon();  // γ_n (header)
  defined_ = reference_energy_ > gamma * absoluteEnergyScale(problem, u_free);
}

double ErrorReference::relativeError(const Eigen::MatrixXd& lambda) const {
  if (!defined_) return std::numeric_limits<double>::quiet_NaN();
  const Eigen::MatrixXd d = lambda - lambda_ref_;
  const double numerator = (d.cwiseProduct(delassus_ * d)).sum();
  return std::sqrt(std::max(numerator, 0.0) / reference_energy_);
}

}  // namespace stc
