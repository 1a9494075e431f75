#include "fas/apriori_basis.hpp"

#include <algorithm>
#include <cmath>

#include "fas/residual_vectors.hpp"
#include "src/core/option_check.hpp"
#include "src/solver/warm_start.hpp"

namespace stc::fas {

void AprioriBasisOptions::validate() const {
  constexpr const char* owner = "a priori basis";
  requireOption(residual_vectors >= 0, owner, "residual_vectors", residual_vectors, "must be >= 0");
  requireOption(modes_per_cycle >= 1, owner, "modes_per_cycle", modes_per_cycle, "must be >= 1");
  requireOption(max_modes >= 0, owner, "max_modes", max_modes, "must be >= 0");
  requireOption(seed_share >= 0.0 && seed_share <= 1.0, owner, "seed_share", seed_share, "must be in [0, 1]");
  requireOption(relative_energy_drop >= 0.0 && std::isfinite(relative_energy_drop), owner, "relative_energy_drop",
                relative_energy_drop, "must be >= 0 and finite");
  requireOption(enrichment.max_sweeps >= 1, owner, "enrichment.max_sweeps", enrichment.max_sweeps, "must be >= 1");
}

AprioriBasisProvider::AprioriBasisProvider(const Problem& problem, const Eigen::SparseMatrix<double>& A,
                                           AprioriBasisOptions options)
    : problem_(problem),
      A_(A),
      options_((options.validate(), options)),
      loads_(pgd::separatedLoads(problem)),
      modes_(A, problem.contact.B, loads_.F) {}

int AprioriBasisProvider::seed(const Eigen::MatrixXd& vectors) {
  requireFits(vectors, problem_);
  const int most = static_cast<int>(options_.seed_share * options_.max_modes);
  for (Eigen::Index j = 0; j < vectors.cols() && modes_.rank() < most; ++j) modes_.add(vectors.col(j));
  return modes_.rank();
}

Eigen::MatrixXd AprioriBasisProvider::enrich(const Eigen::MatrixXd& u_tilde, const Eigen::MatrixXd& W) {
  const pgd::SpaceProblem space = [&](const Eigen::RowVectorXd& psi) {
    return Eigen::VectorXd(u_tilde * psi.transpose());  // A⁻¹ Σ_k ψ_k r_k = ũ ψᵀ
  };
  const pgd::TimeProblem time = pgd::separatedTimeProblem(modes_, loads_.G, W);
  // Energy of ũ_k: ũ_kᵀ A ũ_k = ũ_kᵀ r_k = (Fᵀ ũ_k)·g_k + (B ũ_k)·w_k; of what the modes miss:
  // ‖ũ_k − Υ c_k‖²_A = ũ_kᵀ A ũ_k − ‖c_k‖² (Υ A-orthonormal); a new pair's ψ is its row of c.
  const Eigen::MatrixXd Bu = problem_.contact.B * u_tilde;
  Eigen::RowVectorXd energy = Bu.cwiseProduct(W).colwise().sum();
  if (loads_.F.cols() > 0) energy += (loads_.F.transpose() * u_tilde).cwiseProduct(loads_.G).colwise().sum();
  Eigen::MatrixXd coordinates = pgd::updateTimeFunctions(modes_, loads_.G, W);
  const double total = std::sqrt(std::max(0.0, energy.sum()));
  for (int added = 0; added < options_.modes_per_cycle && modes_.rank() < options_.max_modes; ++added) {
    const Eigen::RowVectorXd missed = (energy - coordinates.colwise().squaredNorm()).cwiseMax(0.0).cwiseSqrt();
    const pgd::RankOnePair pair = pgd::enrichRankOne(modes_, space, time, missed, options_.enrichment);
    if (!(pair.time.norm() > options_.relative_energy_drop * total) || !modes_.add(pair.space)) break;
    coordinates.conservativeResize(coordinates.rows() + 1, Eigen::NoChange);
    coordinates.row(coordinates.rows() - 1) = time(modes_.modes().col(modes_.rank() - 1));
  }
  return coordinates;
}

CoarseSpace AprioriBasisProvider::coarseSpace(const Eigen::MatrixXd& u_tilde, const InterfaceHistory& s) {
  // The last global stage's right-hand sides: λ̂ + k v̂ = λ + k v (docs/method.md §2, search direction).
  const Eigen::MatrixXd W = s.lambda + problem_.contact.search_direction.asDiagonal() * s.v;
  const Eigen::MatrixXd coordinates = enrich(u_tilde, W);
  Eigen::MatrixXd missed = u_tilde;
  if (modes_.rank() > 0) missed.noalias() -= modes_.modes() * coordinates;
  const Eigen::MatrixXd res = rangeOf(missed, options_.residual_vectors);
  Eigen::MatrixXd all(modes_.modes().rows(), modes_.rank() + res.cols());
  all << modes_.modes(), res;
  return CoarseSpace(all, A_, problem_.contact.B);
}

}  // namespace stc::fas
