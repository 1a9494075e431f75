#include "stcontact/pgd/space_time_svd.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/linalg/dense_decompositions.hpp"
#include "stcontact/pgd/arpack_eigen.hpp"

namespace stc::pgd {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// Sign convention: each ν_i has a positive entry of largest magnitude; Υ_i flips with it, so that
// σ_i Υ_i ν_iᵀ is unchanged and two methods return comparable pairs.
void fixSigns(SpaceTimeSvd& s) {
  for (int i = 0; i < s.size(); ++i) {
    Eigen::Index at = 0;
    s.time.col(i).cwiseAbs().maxCoeff(&at);
    if (s.time(at, i) < 0.0) {
      s.time.col(i) *= -1.0;
      s.space.col(i) *= -1.0;
    }
  }
}

// From the leading eigenpairs (λ_i descending, ν_i) of C = UᵀKU: σ_i = √max(λ_i, 0) and
// Υ_i = U ν_i / σ_i above the floor σ_1 √(m ε) (header: "Resolution"), Υ_i = 0 below it.
SpaceTimeSvd fromGram(const Eigen::MatrixXd& U, const Eigen::VectorXd& lambda, Eigen::MatrixXd nu, double total) {
  SpaceTimeSvd s;
  const Eigen::Index r = lambda.size();
  s.sigma = lambda.cwiseMax(0.0).cwiseSqrt();
  s.time = std::move(nu);
  s.total_energy = total;
  s.space = Eigen::MatrixXd::Zero(U.rows(), r);
  const double floor = r > 0 ? s.sigma[0] * std::sqrt(static_cast<double>(U.cols()) * kEpsilon) : 0.0;
  for (Eigen::Index i = 0; i < r && s.sigma[i] > floor; ++i) {
    s.space.col(i) = U * s.time.col(i) / s.sigma[i];
    ++s.resolved;
  }
  fixSigns(s);
  return s;
}

SpaceTimeSvd denseEnergySvd(const Eigen::MatrixXd& U, const Eigen::SparseMatrix<double>& K, int r, double total) {
  const Eigen::MatrixXd KU = K * U;
  Eigen::MatrixXd C = U.transpose() * KU;
  C = 0.5 * (C + C.transpose()).eval();  // symmetric to the last bit before the eigensolver
  const linalg::SymmetricEigen eigen = linalg::symmetricEigen(C);
  if (!eigen.converged) throw std::runtime_error("energySvd: Eigen's SelfAdjointEigenSolver failed");
  // Eigen orders eigenvalues ascending: take the last r, reversed.
  const Eigen::VectorXd lambda = eigen.values.tail(r).reverse();
  const Eigen::MatrixXd nu = eigen.vectors.rightCols(r).rowwise().reverse();
  return fromGram(U, lambda, nu, total);
}

SpaceTimeSvd arpackEnergySvd(const Eigen::MatrixXd& U, const Eigen::SparseMatrix<double>& K,
                             const EnergySvdOptions& options, double total) {
  ArpackOptions arpack;
  arpack.eigenvalues = options.modes;
  arpack.subspace = options.subspace;
  arpack.tolerance = options.tolerance;
  arpack.max_restarts = options.max_restarts;
  arpack.which = ArpackWhich::LargestAlgebraic;
  ArpackEigen solver(static_cast<int>(U.cols()), arpack);
  // y = Uᵀ (K (U x)) / ‖U‖²_K: three products, C is never formed (docs/method.md §3, "truncated").
  Eigen::VectorXd Ux(U.rows()), KUx(U.rows());
  const double scale = 1.0 / total;
  const ArpackResult result = solver.compute(
      [&](const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) {
        Ux.noalias() = U * x;
        KUx.noalias() = K * Ux;
        y.noalias() = U.transpose() * KUx;
        y *= scale;
      });
  SpaceTimeSvd s = fromGram(U, result.values * total, result.vectors, total);
  s.operator_applications = result.operator_applications;
  return s;
}

}  // namespace

void EnergySvdOptions::validate(int m) const {
  const auto bad = [](const std::string& field, const std::string& value, const std::string& rule) {
    throw InputError("energy SVD option " + field + " = " + value + " is invalid: " + rule);
  };
  if (m < 1) bad("m (instants)", std::to_string(m), "must be >= 1");
  if (method == SvdMethod::Dense && (modes < 0 || modes > m))
    bad("modes", std::to_string(modes), "must be in [0, m] = [0, " + std::to_string(m) + "] (0: all)");
  if (method == SvdMethod::Arpack && (modes < 1 || modes >= m))
    bad("modes", std::to_string(modes),
        "must be in [1, m - 1] = [1, " + std::to_string(m - 1) + "] with ARPACK (use the dense method for all m)");
  if (!(tolerance >= 0.0) || tolerance >= 1.0) bad("tolerance", std::to_string(tolerance), "must be in [0, 1)");
  if (subspace != 0 && method == SvdMethod::Arpack && (subspace <= modes || subspace > m))
    bad("subspace", std::to_string(subspace), "must be 0 (automatic) or in (modes, m]");
  if (max_restarts < 1) bad("max_restarts", std::to_string(max_restarts), "must be >= 1");
}

double SpaceTimeSvd::energyFraction(int i) const {
  return total_energy > 0.0 ? sigma[i] * sigma[i] / total_energy : 0.0;
}

double SpaceTimeSvd::cumulativeEnergy(int i) const {
  return total_energy > 0.0 ? sigma.head(i + 1).squaredNorm() / total_energy : 0.0;
}

std::optional<int> SpaceTimeSvd::modesFor(double fraction) const {
  if (!(total_energy > 0.0)) return std::nullopt;
  double sum = 0.0;
  for (int i = 0; i < size(); ++i) {
    sum += sigma[i] * sigma[i];
    if (sum >= fraction * total_energy) return i + 1;
  }
  return std::nullopt;
}

Eigen::MatrixXd SpaceTimeSvd::reconstruct(int r) const {
  r = std::clamp(r, 0, size());
  return space.leftCols(r) * sigma.head(r).asDiagonal() * time.leftCols(r).transpose();
}

double squaredEnergyNorm(const Eigen::MatrixXd& U, const Eigen::SparseMatrix<double>& K) {
  double sum = 0.0;
  Eigen::VectorXd Ku(U.rows());
  for (Eigen::Index k = 0; k < U.cols(); ++k) {
    Ku.noalias() = K * U.col(k);
    sum += U.col(k).dot(Ku);
  }
  return sum;
}

SpaceTimeSvd plainSvd(const Eigen::MatrixXd& U, int modes) {
  const int full = static_cast<int>(std::min(U.rows(), U.cols()));
  if (modes < 0 || modes > full)
    throw InputError("plainSvd: modes = " + std::to_string(modes) + " must be in [0, " + std::to_string(full) + "]");
  const int r = modes == 0 ? full : modes;
  const linalg::Svd svd =
      linalg::singularValueDecomposition(U, linalg::SvdMethod::divide_and_conquer, linalg::kThinU | linalg::kThinV);
  SpaceTimeSvd s;
  s.sigma = svd.values.head(r);
  s.space = svd.U.leftCols(r);
  s.time = svd.V.leftCols(r);
  s.total_energy = U.squaredNorm();
  // A backward-stable SVD resolves σ_i down to ~ max(n, m) ε σ_1.
  const double floor = r > 0 ? s.sigma[0] * static_cast<double>(std::max(U.rows(), U.cols())) * kEpsilon : 0.0;
  s.resolved = static_cast<int>((s.sigma.array() > floor).count());
  fixSigns(s);
  return s;
}

SpaceTimeSvd energySvd(const Eigen::MatrixXd& U, const Eigen::SparseMatrix<double>& K,
                       const EnergySvdOptions& options) {
  if (K.rows() != K.cols() || K.rows() != U.rows())
    throw InputError("energySvd: K is " + std::to_string(K.rows()) + " x " + std::to_string(K.cols()) +
                     " but U has " + std::to_string(U.rows()) + " rows");
  const int m = static_cast<int>(U.cols());
  options.validate(m);
  const int r = options.modes == 0 ? m : options.modes;
  const double total = squaredEnergyNorm(U, K);
  if (!std::isfinite(total)) throw InputError("energySvd: the history has a non-finite energy");
  if (total <= 0.0) {  // no deformation at all: every σ is zero, any orthonormal ν will do
    SpaceTimeSvd s;
    s.sigma = Eigen::VectorXd::Zero(r);
    s.space = Eigen::MatrixXd::Zero(U.rows(), r);
    s.time = Eigen::MatrixXd::Identity(m, r);
    return s;
  }
  return options.method == SvdMethod::Dense ? denseEnergySvd(U, K, r, total) : arpackEnergySvd(U, K, options, total);
}

}  // namespace stc::pgd
