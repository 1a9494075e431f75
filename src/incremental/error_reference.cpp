#include "stcontact/incremental/error_reference.hpp"

#include <cmath>
#include <limits>

#include "stcontact/operators/displacement.hpp"

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

ErrorReference::ErrorReference(const Problem& problem, const SpdSolver& stiffness_free, Eigen::MatrixXd delassus,
                               Eigen::MatrixXd lambda_ref)
    : delassus_(std::move(delassus)), lambda_ref_(std::move(lambda_ref)) {
  setReferenceEnergy(problem, stiffness_free);
}

ErrorReference::ErrorReference(const Problem& problem, std::shared_ptr<const SpdSolver> stiffness_free,
                               Eigen::MatrixXd lambda_ref)
    : factor_(std::move(stiffness_free)),
      lazy_(std::make_unique<LazyDelassus>(problem, *factor_)),
      contact_(&problem.contact),
      lambda_ref_(std::move(lambda_ref)) {
  setReferenceEnergy(problem, *factor_);
}

ErrorReference::~ErrorReference() = default;

void ErrorReference::setReferenceEnergy(const Problem& problem, const SpdSolver& stiffness_free) {
  const Eigen::MatrixXd u_free = freeDisplacements(problem, stiffness_free, lambda_ref_);
  reference_energy_ = spaceTimeEnergy(problem, u_free);
  const double gamma = problem.numDofs() * std::numeric_limits<double>::epsilon();  // γ_n (header)
  defined_ = reference_energy_ > gamma * absoluteEnergyScale(problem, u_free);
}

int ErrorReference::nodesComputed() const {
  if (!lazy_) return 0;
  const std::lock_guard<std::mutex> lock(lazy_mutex_);
  return lazy_->nodesComputed();
}

// Held rows move nothing (their B row is empty), so their forces are left out; LazyDelassus gives
// them a compliance that belongs to the incremental solver only.
double ErrorReference::lazyEnergy(Eigen::MatrixXd d) const {
  const int dim = contact_->dimension;
  for (int r : contact_->held_rows) d.row(r).setZero();
  std::vector<int> support, rows;
  for (int i = 0; i < contact_->size(); ++i)
    if (d.middleRows(static_cast<Eigen::Index>(dim) * i, dim).cwiseAbs().maxCoeff() > 0.0) {
      support.push_back(i);
      for (int a = 0; a < dim; ++a) rows.push_back(dim * i + a);
    }
  const auto n = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd w(n, n);
  {
    const std::lock_guard<std::mutex> lock(lazy_mutex_);
    lazy_->ensure(support);
    for (Eigen::Index q = 0; q < n; ++q)
      for (Eigen::Index p = 0; p < n; ++p) w(p, q) = lazy_->entry(rows[p], rows[q] / dim, rows[q] % dim);
  }
  const Eigen::MatrixXd d_s = d(rows, Eigen::all);
  return (d_s.cwiseProduct(w * d_s)).sum();
}

double ErrorReference::relativeError(const Eigen::MatrixXd& lambda) const {
  if (!defined_) return std::numeric_limits<double>::quiet_NaN();
  const Eigen::MatrixXd d = lambda - lambda_ref_;
  const double numerator = lazy_ ? lazyEnergy(d) : (d.cwiseProduct(delassus_ * d)).sum();
  return std::sqrt(std::max(numerator, 0.0) / reference_energy_);
}

}  // namespace stc
