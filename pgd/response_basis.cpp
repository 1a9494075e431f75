#include "pgd/response_basis.hpp"

#include "pgd/separated_loads.hpp"

namespace stc::pgd {

ResponseBasis::ResponseBasis(const Problem& problem, const SpdFactor& factor)
    : problem_(problem), factor_(factor) {
  const Eigen::VectorXd& k = problem.contact.search_direction;
  sqrt_k_ = k.cwiseSqrt();
  inv_sqrt_k_ = sqrt_k_.cwiseInverse();
  const int rows = static_cast<int>(k.size());
  Z_.resize(rows, 0);
  Zs_.resize(rows, 0);
  T_.resize(rows, 0);
  X_.resize(problem.numFreeDofs(), 0);
  const SeparatedLoads loads = separatedLoads(problem);
  G_ = loads.G;
  UF_ = loads.F.cols() > 0 ? factor.solve(loads.F) : Eigen::MatrixXd(problem.numFreeDofs(), 0);
  sparse_solves_ += UF_.cols();
  VF_ = problem.contact.B * UF_;
  UFtF_ = UF_.transpose() * loads.F;
  v0_ = VF_ * G_;
}

int ResponseBasis::append(const Eigen::MatrixXd& candidates, double drop) {
  // Work with scaled directions ẑ = k^{-1/2} z, orthonormal in the Euclidean product.
  Eigen::MatrixXd scaled = Zs_;
  Eigen::MatrixXd kept(Z_.rows(), 0);
  for (Eigen::Index j = 0; j < candidates.cols() && scaled.cols() < Z_.rows(); ++j) {
    Eigen::VectorXd y = inv_sqrt_k_.asDiagonal() * candidates.col(j);
    const double original = y.norm();
    if (!(original > 0.0)) continue;
    for (int pass = 0; pass < 2 && scaled.cols() > 0; ++pass) y -= scaled * (scaled.transpose() * y);
    const double norm = y.norm();
    if (!(norm > drop * original)) continue;
    scaled.conservativeResize(Eigen::NoChange, scaled.cols() + 1);
    scaled.col(scaled.cols() - 1) = y / norm;
    kept.conservativeResize(Eigen::NoChange, kept.cols() + 1);
    kept.col(kept.cols() - 1) = sqrt_k_.asDiagonal() * (y / norm);
  }
  const Eigen::Index added = kept.cols(), p = Z_.cols();
  if (added == 0) return 0;
  const auto& B = problem_.contact.B;
  const Eigen::MatrixXd X = factor_.solve(Eigen::MatrixXd(B.transpose() * kept));
  sparse_solves_ += added;
  Z_.conservativeResize(Eigen::NoChange, p + added);
  Z_.rightCols(added) = kept;
  Zs_ = std::move(scaled);
  X_.conservativeResize(Eigen::NoChange, p + added);
  X_.rightCols(added) = X;
  T_.conservativeResize(Eigen::NoChange, p + added);
  T_.rightCols(added) = B * X;
  return static_cast<int>(added);
}

}  // namespace stc::pgd
