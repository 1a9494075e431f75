#include "pgd/separated_global_stage.hpp"

#include <cmath>

#include "src/solver/warm_start.hpp"

namespace stc::pgd {

SeparatedGlobalStage::SeparatedGlobalStage(const Problem& problem, const latin::GlobalStage& global)
    : problem_(problem),
      global_(global),
      loads_(separatedLoads(problem)),
      modes_(global.matrix(), problem.contact.B, loads_.F) {}

int SeparatedGlobalStage::seed(const Eigen::MatrixXd& vectors, int max_rank) {
  requireFits(vectors, problem_);
  for (Eigen::Index j = 0; j < vectors.cols() && modes_.rank() < max_rank; ++j) modes_.add(vectors.col(j));
  return modes_.rank();
}

void SeparatedGlobalStage::update(const InterfaceHistory& hat, InterfaceHistory& s) {
  const Eigen::VectorXd& k = problem_.contact.search_direction;
  W_ = hat.lambda + k.asDiagonal() * hat.v;
  if (modes_.rank() == 0) {
    s.v = Eigen::MatrixXd::Zero(hat.v.rows(), hat.v.cols());
  } else {
    s.v.noalias() = modes_.interface() * updateTimeFunctions(modes_, loads_.G, W_);
  }
  s.lambda = hat.lambda - k.asDiagonal() * (s.v - hat.v);
}

RankOnePair SeparatedGlobalStage::candidate(const EnrichmentOptions& options) {
  const auto& B = problem_.contact.B;
  // x = A⁻¹ Σ_k ψ_k r_k = A⁻¹ (F (G ψᵀ) + Bᵀ (W ψᵀ)): one sparse solve.
  const SpaceProblem solve = [&](const Eigen::RowVectorXd& psi) {
    Eigen::VectorXd rhs = B.transpose() * (W_ * psi.transpose());
    if (loads_.F.cols() > 0) rhs.noalias() += loads_.F * (loads_.G * psi.transpose());
    ++sparse_solves_;
    return Eigen::VectorXd(global_.factor().solve(rhs));
  };
  // Start from the size of the right-hand side at each instant: the loading's own time profile.
  const Eigen::RowVectorXd psi0 = W_.colwise().norm() + loads_.G.colwise().norm();
  return enrichRankOne(modes_, solve, separatedTimeProblem(modes_, loads_.G, W_), psi0, options);
}

double SeparatedGlobalStage::interfaceNorm(const RankOnePair& pair) const {
  if (pair.space.size() == 0) return 0.0;
  const Eigen::VectorXd By = problem_.contact.B * pair.space;
  const double v_part = By.dot(problem_.contact.search_direction.asDiagonal() * By);
  return std::sqrt(2.0 * v_part) * pair.time.norm();  // ‖δv‖²_k + ‖k δv‖²_{k⁻¹} = 2 ‖δv‖²_k
}

}  // namespace stc::pgd
