#include "stcontact/incremental/reach_zone.hpp"

#include <algorithm>

#include "stcontact/incremental/lazy_delassus.hpp"
#include "stcontact/linalg/low_rank_solve.hpp"
#include "stcontact/problem/prescribed_reach.hpp"

namespace stc {

std::optional<std::vector<int>> reachZone(const Problem& problem) {
  const std::optional<Eigen::MatrixXd> w = prescribedTranslation(problem);
  if (!w) return std::nullopt;
  std::vector<int> zone = nodesWithinReach(problem.contact, *w, 0.0);
  if (zone.empty() || static_cast<int>(zone.size()) == problem.contact.size()) return std::nullopt;
  return zone;
}

ZoneCondensation ZoneCondensation::build(const Problem& problem, const SpdSolver& stiffness_free,
                                         std::vector<int> zone) {
  const ContactInterface& contact = problem.contact;
  const int d = contact.dimension;
  ZoneCondensation c;
  c.far = otherNodes(contact.size(), zone);
  c.zone = std::move(zone);
  const std::vector<int> rows = rowsOfNodes(d, c.zone), far_rows = rowsOfNodes(d, c.far);
  c.B_zone = restrictToNodes(contact, c.zone).B;
  c.B_far = restrictToNodes(contact, c.far).B;
  c.on_zone.sparse_solves = static_cast<int>(problem.loads.size());
  if (stiffness_free.condenses(c.B_zone)) {
    c.on_zone.delassus = stiffness_free.condensed(c.B_zone);
  } else {
    const Eigen::MatrixXd responses = stiffness_free.solveOnThreads(Eigen::MatrixXd(c.B_zone.transpose()));  // K⁻¹ B_Zᵀ
    c.on_zone.delassus = symmetricDelassus(c.B_zone, responses);
    c.far_delassus = c.B_far * responses;
    c.on_zone.sparse_solves += static_cast<int>(rows.size());
  }
  const Eigen::MatrixXd free = freeInterfaceResponse(problem, stiffness_free);
  c.on_zone.free_response = free(rows, Eigen::all);
  c.far_free = free(far_rows, Eigen::all);
  return c;
}

InterfaceHistory ZoneCondensation::lift(const ContactInterface& contact, const SpdSolver& stiffness_free,
                                        const InterfaceHistory& on_zone, int solved, long& sparse_solves) const {
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
  else  // W_FZ λ_Z = B_F K⁻¹ B_Zᵀ λ_Z with rank(λ_Z) half-solves (linalg/low_rank_solve.hpp)
    v_far += linalg::solveThroughRank(stiffness_free, B_far, B_zone, lambda_zone, sparse_solves);
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
