#include "pgd/separated_history.hpp"

#include <Eigen/Eigenvalues>

namespace stc::pgd {
namespace {

// ΦᵀAΦ for Φ = [U_F X], from traces (header).
Eigen::MatrixXd gram(const ResponseBasis& basis) {
  const Eigen::Index q = basis.loadResponses().cols(), p = basis.size();
  Eigen::MatrixXd M(q + p, q + p);
  M.topLeftCorner(q, q) = basis.loadEnergy();
  M.topRightCorner(q, p) = basis.loadTraces().transpose() * basis.directions();
  M.bottomLeftCorner(p, q) = M.topRightCorner(q, p).transpose();
  M.bottomRightCorner(p, p) = basis.traces().transpose() * basis.directions();
  return 0.5 * (M + M.transpose());
}

}  // namespace

Eigen::MatrixXd historyFactor(const ResponseBasis& basis, const Eigen::MatrixXd& c) {
  const Eigen::MatrixXd& G = basis.loadHistories();
  Eigen::MatrixXd theta = Eigen::MatrixXd::Zero(G.rows() + basis.size(), G.cols());
  theta.topRows(G.rows()) = G;
  theta.middleRows(G.rows(), c.rows()) = c;
  return theta;
}

Whitening whitening(const ResponseBasis& basis) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(gram(basis));
  const Eigen::VectorXd& d = eig.eigenvalues();  // ascending
  const double largest = d.size() > 0 ? d.maxCoeff() : 0.0;
  int keep = 0;
  for (Eigen::Index j = 0; j < d.size(); ++j) keep += d[j] > 1e-14 * largest;
  const Eigen::MatrixXd V = eig.eigenvectors().rightCols(keep);
  const Eigen::VectorXd sqrt_d = d.tail(keep).cwiseSqrt();
  return {V * sqrt_d.cwiseInverse().asDiagonal(), sqrt_d.asDiagonal() * V.transpose()};
}

Eigen::MatrixXd leadingSingularVectors(const Eigen::MatrixXd& coordinates, int count, double drop) {
  // Left singular vectors from the eigenvectors of Θ̂ Θ̂ᵀ (s' × s', s' ≪ m).
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(coordinates * coordinates.transpose());
  const Eigen::VectorXd& d = eig.eigenvalues();  // ascending: σ²
  const Eigen::Index size = d.size();
  int keep = 0;
  while (keep < count && keep < size && d[size - 1 - keep] > drop * drop * d[size - 1]) ++keep;
  return eig.eigenvectors().rightCols(keep).rowwise().reverse();
}

EnergySvd energySvd(const ResponseBasis& basis, const Eigen::MatrixXd& c, int count, double drop) {
  const Whitening w = whitening(basis);
  const Eigen::MatrixXd coordinates = w.to_coordinates * historyFactor(basis, c);
  const Eigen::MatrixXd U = leadingSingularVectors(coordinates, count, drop);
  EnergySvd svd;
  svd.combination = w.to_modes * U;
  svd.time_functions = U.transpose() * coordinates;
  svd.singular_values = svd.time_functions.rowwise().norm();
  return svd;
}

Eigen::MatrixXd spatialModes(const ResponseBasis& basis, const Eigen::MatrixXd& combination) {
  const Eigen::Index q = basis.loadResponses().cols();
  Eigen::MatrixXd Y = basis.loadResponses() * combination.topRows(q);
  Y.noalias() += basis.responses() * combination.bottomRows(combination.rows() - q);
  return Y;
}

Eigen::MatrixXd modeTraces(const ResponseBasis& basis, const Eigen::MatrixXd& combination) {
  const Eigen::Index q = basis.loadTraces().cols();
  Eigen::MatrixXd BY = basis.loadTraces() * combination.topRows(q);
  BY.noalias() += basis.traces() * combination.bottomRows(combination.rows() - q);
  return BY;
}

Eigen::MatrixXd energyModes(const ResponseBasis& basis, const Eigen::MatrixXd& c) {
  const int all = static_cast<int>(basis.loadResponses().cols()) + basis.size();
  return spatialModes(basis, energySvd(basis, c, all).combination);
}

}  // namespace stc::pgd
