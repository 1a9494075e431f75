#include "stcontact/incremental/cone_newton.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <sstream>

#include "stcontact/contact/contact_interface.hpp"
#include "stcontact/incremental/cone_piece.hpp"
#include "stcontact/incremental/newton_instant.hpp"

namespace stc {
namespace {

using TangentMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 2, 2>;

}  // namespace

ConeLaw::ConeLaw(const Problem& problem, LazyDelassus& delassus)
    : contact_(problem.contact),
      W_(delassus),
      d_(problem.contact.dimension),
      rho_n_(Eigen::VectorXd::Zero(problem.contact.size())),
      rho_t_(Eigen::VectorXd::Zero(problem.contact.size())) {}

void ConeLaw::setInstant(const Eigen::VectorXd& v0, const Eigen::VectorXd& v_previous) {
  v0_ = v0;
  v_previous_ = v_previous;
}

InstantOutcome ConeLaw::solveInstant(const Eigen::VectorXd& v0, const Eigen::VectorXd& lambda_previous,
                                     const Eigen::VectorXd& v_previous, const IncrementalOptions& options) {
  setInstant(v0, v_previous);
  return solveInstantByNewton(*this, lambda_previous, options.tolerance, options.max_newton_iterations);
}

std::string ConeLaw::systemsRemark() const {
  const linalg::RowUpdatedLu::Counts& systems = newtonSystems();
  std::ostringstream note;
  note << "Newton systems: " << systems.factorisations << " LU factorisations, " << systems.updates
       << " solved by updating one (" << systems.rejected << " updates rejected)";
  return note.str();
}

// v = v_0 + W λ over the nodes that carry a force (their columns exist: a force only appears on a
// node after it closed).
Eigen::VectorXd ConeLaw::displacement(const Eigen::VectorXd& lambda) const {
  Eigen::VectorXd v = v0_;
  for (int j = 0; j < contact_.size(); ++j)
    for (int a = 0; a < d_; ++a)
      if (const double l = lambda[d_ * j + a]; l != 0.0) v.noalias() += W_.column(j, a) * l;
  return v;
}

// Computes the columns of `nodes` and their ρ_n = 1 / W_nn, ρ_t = (d − 1) / tr(W_tt).
void ConeLaw::learnScaling(const std::vector<int>& nodes) {
  W_.ensure(nodes);
  for (int i : nodes) {
    const int n = d_ * i;
    rho_n_[i] = 1.0 / W_.entry(n, i, 0);
    double trace = 0.0;
    for (int a = 1; a < d_; ++a) trace += W_.entry(n + a, i, a);
    rho_t_[i] = (d_ - 1) / trace;
    rho_max_ = std::max({rho_max_, rho_n_[i], rho_t_[i]});
  }
}

void ConeLaw::nodeLaw(int i, const Eigen::VectorXd& lambda, Evaluation& e) const {
  const int n = d_ * i, t = n + 1, dt = d_ - 1;
  auto A = e.A.middleCols(n, d_), C = e.C.middleCols(n, d_);
  A.setZero();
  C.setZero();
  const Tangent s = e.v.segment(t, dt) - v_previous_.segment(t, dt);
  const ConePiece p = conePiece(lambda[n], lambda.segment(t, dt), contact_.initial_gap[i] + e.v[n], s, rho_n_[i],
                                rho_t_[i], contact_.friction);
  e.F[n] = p.F_n;
  e.F.segment(t, dt) = p.F_t;
  if (p.state == ContactState::Open) {
    A.setIdentity();
    return;
  }
  e.closed[i] = true;
  C(0, 0) = rho_n_[i];
  if (p.state == ContactState::Stick) {
    C.bottomRightCorner(dt, dt).diagonal().setConstant(rho_t_[i]);
    return;
  }
  const TangentMatrix P = TangentMatrix::Identity(dt, dt) - p.unit * p.unit.transpose();
  A.bottomRightCorner(dt, dt) = TangentMatrix::Identity(dt, dt) - p.q * P;
  A.bottomLeftCorner(dt, 1) = -contact_.friction * p.unit;
  C.bottomLeftCorner(dt, 1) = contact_.friction * rho_n_[i] * p.unit;
  C.bottomRightCorner(dt, dt) = p.q * rho_t_[i] * P;
}

ConeLaw::Evaluation ConeLaw::evaluate(const Eigen::VectorXd& lambda) {
  const int nc = contact_.size();
  Evaluation e{displacement(lambda), Eigen::VectorXd(lambda.size()), std::vector<bool>(nc, false),
               Eigen::MatrixXd(d_, d_ * nc), Eigen::MatrixXd(d_, d_ * nc)};
  std::vector<int> entering;  // nodes without columns that are about to close
  for (int i = 0; i < nc; ++i)
    if (!W_.has(i) && contact_.initial_gap[i] + e.v[d_ * i] < 0.0) entering.push_back(i);
  if (!entering.empty()) learnScaling(entering);
  for (int i = 0; i < nc; ++i) nodeLaw(i, lambda, e);
  return e;
}

// (A_CC + C_CC W_CC) Δλ_C = −F_C + C_CC W_CO λ_O, one block row of D per closed node (D × D
// blocks of fixed size: these products are most of the step's arithmetic outside the LU). A block
// row depends on its node's A and C alone while the closed set stays, so it is formed again only
// when they changed (a slipping node's, or a node that changed status): the same matrix, without
// the stuck nodes' rows formed and compared at every step.
template <int D>
std::vector<Eigen::Index> ConeLaw::newtonSystem(const std::vector<int>& closed, const Evaluation& e,
                                                const Eigen::VectorXd& open_response, bool rebuilt, Eigen::VectorXd& rhs) {
  std::vector<Eigen::Index> changed;
  for (Eigen::Index p = 0; p < static_cast<Eigen::Index>(closed.size()); ++p) {
    const Eigen::Index n = D * closed[p];
    const Eigen::Matrix<double, D, D> A = e.A.middleCols<D>(n), C = e.C.middleCols<D>(n);
    rhs.segment<D>(D * p).noalias() = C * open_response.segment<D>(D * p) - e.F.segment<D>(n);
    if (!rebuilt && A == formed_A_.middleCols<D>(D * p) && C == formed_C_.middleCols<D>(D * p)) continue;
    M_.middleRows<D>(D * p).noalias() = C * W_CC_.middleRows<D>(D * p);
    M_.block<D, D>(D * p, D * p) += A;
    formed_A_.middleCols<D>(D * p) = A;
    formed_C_.middleCols<D>(D * p) = C;
    for (Eigen::Index a = 0; a < D; ++a) changed.push_back(D * p + a);
  }
  return changed;
}

bool ConeLaw::newtonStep(const Eigen::VectorXd& lambda, const Evaluation& e, Eigen::VectorXd& step) {
  std::vector<int> closed, forced_open;
  for (int i = 0; i < contact_.size(); ++i) {
    if (e.closed[i]) closed.push_back(i);
    else if (lambda.segment(d_ * i, d_).squaredNorm() > 0.0) forced_open.push_back(i);
  }
  const std::vector<int> rows = rowsOfNodes(d_, closed);
  const auto nA = static_cast<Eigen::Index>(rows.size());
  // W_CC gathered from the closed nodes' columns (once per closed set), and W_CO λ_O, the open
  // nodes' forces that Δλ_O = −λ_O removes (−C W_CO Δλ_O moves to the right-hand side).
  const bool rebuilt = closed != closed_;
  if (rebuilt) {
    W_CC_.resize(nA, nA);
    for (Eigen::Index q = 0; q < nA; ++q) W_CC_.col(q) = W_.column(closed[q / d_], static_cast<int>(q % d_))(rows);
    closed_ = closed;
    M_.resize(nA, nA);
    formed_A_.resize(d_, nA);
    formed_C_.resize(d_, nA);
  }
  Eigen::VectorXd open_response = Eigen::VectorXd::Zero(nA);
  for (int j : forced_open)
    for (int b = 0; b < d_; ++b) open_response += W_.column(j, b)(rows) * lambda[d_ * j + b];
  Eigen::VectorXd rhs(nA);
  const std::vector<Eigen::Index> changed = d_ == 3 ? newtonSystem<3>(closed, e, open_response, rebuilt, rhs)
                                                   : newtonSystem<2>(closed, e, open_response, rebuilt, rhs);
  step = -lambda;
  if (nA > 0) {
    const Eigen::VectorXd x = system_.solve(closed, M_, rhs, changed);
    for (int p = 0; p < static_cast<int>(closed.size()); ++p) step.segment(d_ * closed[p], d_) = x.segment(d_ * p, d_);
  }
  return step.allFinite();
}

double ConeLaw::forceScale(const Eigen::VectorXd& lambda) const {
  return stc::forceScale(lambda, rho_max_, v0_);
}

}  // namespace stc
