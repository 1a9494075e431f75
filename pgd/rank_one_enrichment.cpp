#include "pgd/rank_one_enrichment.hpp"

#include <cmath>

namespace stc::pgd {

Eigen::MatrixXd updateTimeFunctions(const EnergyModes& modes, const Eigen::MatrixXd& G, const Eigen::MatrixXd& W) {
  Eigen::MatrixXd Psi = modes.interface().transpose() * W;
  if (modes.loads().cols() > 0) Psi.noalias() += modes.loadProjection() * G;
  return Psi;
}

namespace {

// Space step: Υ = (I − Υ_m Υ_mᵀ A) x, A-normalised; empty when x lies in span Υ_m.
Eigen::VectorXd orthonormalSpace(const EnergyModes& modes, Eigen::VectorXd x) {
  const auto& A = modes.energy();
  const double original = std::sqrt(std::max(0.0, x.dot(A * x)));
  for (int pass = 0; pass < 2 && modes.rank() > 0; ++pass) x.noalias() -= modes.modes() * (modes.modes().transpose() * (A * x));
  const double norm = std::sqrt(std::max(0.0, x.dot(A * x)));
  if (!(norm > 1e-12 * original) || !std::isfinite(norm)) return {};
  return x / norm;
}

}  // namespace

TimeProblem separatedTimeProblem(const EnergyModes& modes, const Eigen::MatrixXd& G, const Eigen::MatrixXd& W) {
  return [&modes, &G, &W](const Eigen::VectorXd& space) {
    const Eigen::VectorXd interface = modes.interfaceOperator() * space;
    Eigen::RowVectorXd psi = interface.transpose() * W;
    if (modes.loads().cols() > 0) psi.noalias() += (space.transpose() * modes.loads()) * G;
    return psi;
  };
}

RankOnePair enrichRankOne(const EnergyModes& modes, const SpaceProblem& space_problem,
                          const TimeProblem& time_problem, Eigen::RowVectorXd psi0,
                          const EnrichmentOptions& options) {
  RankOnePair pair;
  pair.time = std::move(psi0);
  for (int sweep = 0; sweep < options.max_sweeps; ++sweep) {
    if (!(pair.time.norm() > 0.0)) break;
    pair.space = orthonormalSpace(modes, space_problem(pair.time));
    ++pair.space_problems;
    if (pair.space.size() == 0) break;
    const Eigen::RowVectorXd previous = pair.time;
    pair.time = time_problem(pair.space);  // Υ is A-orthogonal to the modes
    // ψ is only defined up to the sign and scale of Υ: compare directions.
    const double scale = previous.dot(pair.time) / std::max(previous.squaredNorm(), 1e-300);
    if ((pair.time - scale * previous).norm() <= options.sweep_tolerance * pair.time.norm()) break;
  }
  if (pair.space.size() == 0) pair.time.setZero();
  return pair;
}

}  // namespace stc::pgd
