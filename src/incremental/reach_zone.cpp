#include "stcontact/incremental/reach_zone.hpp"

#include <algorithm>
#include <limits>

#include "stcontact/incremental/lazy_delassus.hpp"
#include "stcontact/linalg/dense_decompositions.hpp"
#include "stcontact/problem/prescribed_reach.hpp"

namespace stc {

std::optional<std::vector<int>> reachZone(const Problem& problem) {
  const std::optional<Eigen::MatrixXd> w = prescribedTranslation(problem);
  if (!w) return std::nullopt;
  std::vector<int> zone = nodesWithinReach(problem.contact, *w, 0.0);
  if (zone.empty() || static_cast<int>(zone.size()) == problem.contact.size()) return std::nullopt;
  return zone;
}

ZoneCondensation ZoneCondensation::build(const Problem& problem, const SpdFactor& stiffness_free,
                                         std::vector<int> zone) {
  const ContactInterface& contact = problem.contact;
  const int d = contact.dimension;
  ZoneCondensation c;
  c.far = otherNodes(contact.size(), zone);
  c.zone = std::move(zone);
  const std::vector<int> rows = rowsOfNodes(d, c.zone), far_rows = rowsOfNodes(d, c.far);
  const Eigen::SparseMatrix<double> B_zone = restrictToNodes(contact, c.zone).B;
  c.on_zone.sparse_solves = static_cast<int>(problem.loads.size());
  if (stiffness_free.condenses(B_zone)) {
    c.on_zone.delassus = stiffness_free.condensed(B_zone);
  } else {
    const Eigen::MatrixXd responses = stiffness_free.solveOnThreads(Eigen::MatrixXd(B_zone.transpose()));  // K⁻¹ B_Zᵀ
    c.on_zone.delassus = symmetricDelassus(B_zone, responses);
    c.far_delassus = restrictToNodes(contact, c.far).B * responses;
    c.on_zone.sparse_solves += static_cast<int>(rows.size());
  }
  const Eigen::MatrixXd free = freeInterfaceResponse(problem, stiffness_free);
  c.on_zone.free_response = free(rows, Eigen::all);
  c.far_free = free(far_rows, Eigen::all);
  return c;
}

namespace {

// W_FZ λ_Z = B_F K⁻¹ B_Zᵀ λ_Z (λ_Z: d |Z| × solved) with as many solves as λ_Z has rank: with its
// SVD λ_Z = U Σ Vᵀ, kept to its numerical rank r (σ_i > max(d |Z|, solved) ε σ_1, what round-off
// cannot tell from zero), W_FZ λ_Z = (B_F K⁻¹ B_Zᵀ U_r) Σ_r V_rᵀ: r ≤ min(d |Z|, solved) solves (134
// for the 201 instants of 801 arc nodes, 82 for the 2001 of 401 × 2001).
Eigen::MatrixXd farResponse(const Problem& problem, const SpdFactor& stiffness_free, const ZoneCondensation& c,
                            const Eigen::MatrixXd& lambda_zone, int& sparse_solves) {
  const Eigen::SparseMatrix<double> B_zone = restrictToNodes(problem.contact, c.zone).B;
  const Eigen::SparseMatrix<double> B_far = restrictToNodes(problem.contact, c.far).B;
  const linalg::Svd svd = linalg::singularValueDecomposition(lambda_zone, linalg::SvdMethod::divide_and_conquer,
                                                             linalg::kThinU | linalg::kThinV);
  const double floor = static_cast<double>(std::max(lambda_zone.rows(), lambda_zone.cols())) *
                       std::numeric_limits<double>::epsilon() * (svd.values.size() > 0 ? svd.values[0] : 0.0);
  Eigen::Index rank = 0;
  while (rank < svd.values.size() && svd.values[rank] > floor) ++rank;
  sparse_solves += static_cast<int>(rank);
  if (rank == 0) return Eigen::MatrixXd::Zero(B_far.rows(), lambda_zone.cols());
  const Eigen::MatrixXd forces = B_zone.transpose() * svd.U.leftCols(rank);
  const Eigen::MatrixXd far = B_far * stiffness_free.solveOnThreads(forces);
  return far * (svd.values.head(rank).asDiagonal() * svd.V.leftCols(rank).transpose());
}

}  // namespace

InterfaceHistory ZoneCondensation::lift(const Problem& problem, const SpdFactor& stiffness_free,
                                        const InterfaceHistory& on_zone, int solved, int& sparse_solves) const {
  const ContactInterface& contact = problem.contact;
  const int d = contact.dimension;
  InterfaceHistory h = InterfaceHistory::zeros(contact, on_zone.numSteps());
  const std::vector<int> rows = rowsOfNodes(d, zone), far_rows = rowsOfNodes(d, far);
  h.lambda(rows, Eigen::all) = on_zone.lambda;
  h.v(rows, Eigen::all) = on_zone.v;
  if (far.empty() || solved == 0) return h;
  const Eigen::MatrixXd lambda_zone = on_zone.lambda.leftCols(solved);
  Eigen::MatrixXd v_far = far_free.leftCols(solved);
  if (far_delassus.size() > 0)
    v_far.noalias() += far_delassus * lambda_zone;
  else
    v_far += farResponse(problem, stiffness_free, *this, lambda_zone, sparse_solves);
  h.v(far_rows, Eigen::seqN(0, solved)) = v_far;
  return h;
}

std::vector<int> penetratingNodes(const ContactInterface& contact, const InterfaceHistory& h,
                                  const std::vector<int>& far, double tolerance) {
  const int d = contact.dimension;
  const double gap_scale = contact.initial_gap.size() > 0 ? contact.initial_gap.cwiseAbs().maxCoeff() : 0.0;
  std::vector<int> penetrating;
  for (int k = 0; k < h.numSteps(); ++k) {
    const double floor = -tolerance * std::max(h.v.col(k).cwiseAbs().maxCoeff(), gap_scale);
    for (int i : far)
      if (!(contact.initial_gap[i] + h.v(d * i, k) >= floor)) penetrating.push_back(i);  // NaN too
  }
  std::sort(penetrating.begin(), penetrating.end());
  penetrating.erase(std::unique(penetrating.begin(), penetrating.end()), penetrating.end());
  return penetrating;
}

}  // namespace stc
