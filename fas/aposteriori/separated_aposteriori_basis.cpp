#include "stcontact/fas/aposteriori/separated_aposteriori_basis.hpp"

#include <Eigen/Eigenvalues>
#include <vector>

#include "stcontact/pgd/separated_history.hpp"

namespace stc::fas {
namespace {

/// Y⊥ directions whose A-norm² (an eigenvalue of I − SᵀS) is below this lie in span Φ: dropped.
constexpr double kOutsideSpan = 1e-10;

}  // namespace

SeparatedAposterioriProvider::SeparatedAposterioriProvider(const Eigen::MatrixXd& modes, int residual_vectors,
                                                           const pgd::ControlledGlobalStage& stage,
                                                           const Eigen::SparseMatrix<double>& B)
    : stage_(stage), fixed_(modes, stage.matrix(), B), residual_vectors_(residual_vectors) {
  AY_ = stage.matrix() * fixed_.basis();
}

CoarseSpace SeparatedAposterioriProvider::coarseSpace(const InterfaceHistory& /*hat*/) {
  if (residual_vectors_ == 0 || stage_.coordinates().size() == 0) return fixed_;
  const Eigen::MatrixXd residual = residualTraces();
  Eigen::MatrixXd traces(fixed_.interface().rows(), fixed_.rank() + residual.cols());
  traces << fixed_.interface(), residual;
  return CoarseSpace::fromTraces(std::move(traces));
}

Eigen::MatrixXd SeparatedAposterioriProvider::residualTraces() const {
  const pgd::ResponseBasis& basis = stage_.basis();
  const pgd::EnergyFactor& factor = basis.energyFactor();
  const Eigen::MatrixXd& BY = fixed_.interface();
  const Eigen::Index q = basis.loadResponses().cols(), p = basis.size(), k = fixed_.rank();
  const Eigen::MatrixXd theta = pgd::whitenedHistory(basis, stage_.coordinates());  // Θ̂
  // S = Φ̂ᵀ A Y from Φᵀ A Y = [U_Fᵀ A Y; Zᵀ B Y].
  Eigen::MatrixXd products(q + p, k);
  products.topRows(q) = basis.loadResponses().transpose() * AY_;
  products.bottomRows(p) = basis.directions().transpose() * BY;
  const Eigen::MatrixXd S = factor.projections(products);
  // Y⊥'s energy Gram I − SᵀS = V D Vᵀ: the directions of Y outside span Φ.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> gram(Eigen::MatrixXd::Identity(k, k) - S.transpose() * S);
  std::vector<Eigen::Index> outside;
  for (Eigen::Index i = 0; i < k; ++i)
    if (gram.eigenvalues()[i] > kOutsideSpan) outside.push_back(i);
  const Eigen::Index kp = static_cast<Eigen::Index>(outside.size()), sp = theta.rows();
  const Eigen::MatrixXd V = gram.eigenvectors()(Eigen::all, outside);
  const Eigen::VectorXd d = gram.eigenvalues()(outside);
  // R = [Θ̂; 0] − Γ (Sᵀ Θ̂), Γ = [S; D^{1/2} Vᵀ].
  const Eigen::MatrixXd along_Y = S.transpose() * theta;
  Eigen::MatrixXd R(sp + kp, theta.cols());
  R.topRows(sp) = theta - S * along_Y;
  R.bottomRows(kp) = -(d.cwiseSqrt().asDiagonal() * V.transpose()) * along_Y;
  const Eigen::MatrixXd U = pgd::leadingSingularVectors(R, residual_vectors_);
  // B [Φ̂, Ŷ⊥] U with B Ŷ⊥ = (B Y − B Φ̂ S) V D^{-1/2}.
  Eigen::MatrixXd traces = pgd::modeTraces(basis, factor.combination(U.topRows(sp)));
  if (kp > 0) {
    const Eigen::MatrixXd BY_outside =
        (BY - pgd::modeTraces(basis, factor.combination(S))) * (V * d.cwiseSqrt().cwiseInverse().asDiagonal());
    traces.noalias() += BY_outside * U.bottomRows(kp);
  }
  return traces;
}

}  // namespace stc::fas
