#include "stcontact/pgd/controlled_global_stage.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "stcontact/core/interruption.hpp"
#include "stcontact/core/threads.hpp"
#include "stcontact/linalg/dense_decompositions.hpp"
#include "stcontact/linalg/dense_product.hpp"
#include "stcontact/linalg/ranks.hpp"
#include "stcontact/pgd/separated_history.hpp"
#include "stcontact/solver/warm_start.hpp"

namespace stc::pgd {
namespace {

// Leading left singular directions of R (rows × m, Frobenius norm `norm`), at most `count`, enough
// that the rest of R's Frobenius norm is at most `target`: randomized range finder with power
// iterations.
Eigen::MatrixXd leadingDirections(const Eigen::MatrixXd& R, double norm, double target, int count,
                                  const ControlledStageOptions& o, unsigned seed) {
  const int samples = std::min<int>({count + o.oversampling, static_cast<int>(R.cols()), static_cast<int>(R.rows())});
  const Eigen::MatrixXd Q = linalg::randomizedRange(R, samples, o.power_iterations, 20131001u + seed);
  const linalg::Svd svd = linalg::singularValueDecomposition(Q.transpose() * R, linalg::SvdMethod::qr_iteration, linalg::kThinU);
  const Eigen::VectorXd& sigma = svd.values;
  double rest = norm * norm;
  int keep = 0;
  while (keep < std::min<int>(count, static_cast<int>(sigma.size())) && sigma[keep] > 0.0 &&
         (keep == 0 || rest > target * target)) {
    rest -= sigma[keep] * sigma[keep];
    ++keep;
  }
  return Q * svd.U.leftCols(keep);
}

// The bytes the responses may hold: the options' share of the memory available to this rank.
double responseBytes(const ControlledStageOptions& options) {
  return options.response_share * availableMemoryOfThisRank();
}

}  // namespace

// An owner of its own, which the stage outlives: the operator stays with the stage's shared pointer.
ControlledGlobalStage::ControlledGlobalStage(const Problem& problem, ControlledStageOptions options)
    : ControlledGlobalStage(problem, options, *std::make_unique<PreparedOperators>()) {}

ControlledGlobalStage::ControlledGlobalStage(const Problem& problem, ControlledStageOptions options,
                                             PreparedOperators& operators)
    : problem_(problem),
      options_(options),
      // the interface's dofs last at any size (header)
      operator_(operators.searchOperator(problem, {dofsReadBy(problem.contact.B), /*min_work=*/0.0})),
      basis_(problem, *operator_->factor, responseBytes(options)) {
  options_.validate();
}

void ControlledGlobalStage::retime(const Problem& grid) {
  basis_.retime(grid);
  c_.resize(0, 0);
  w_last_.resize(0, 0);
  c_stale_ = false;
  target_ = -1.0;
}

int ControlledGlobalStage::seed(const Eigen::MatrixXd& directions) {
  requireFits(directions, problem_);
  const int kept = basis_.appendDirections(directions);
  solvePendingNoted(Eigen::VectorXd(), "seeded");
  return kept;
}

void ControlledGlobalStage::solvePendingNoted(const Eigen::VectorXd& loosening, const std::string& which) {
  // In parts on an iterative backend (the same numbers), told when there is a note, and a caller's
  // stop between them (src/core/interruption.hpp): at 10⁶ dofs a first relaxation's directions take
  // more than ten minutes and make no record.
  NotedPhase phase(note_, "global stage: ", note_interval_);
  basis_.solvePending(loosening, [&](Eigen::Index solved, Eigen::Index pending) {
    stopPoint();
    phase.during(std::to_string(solved) + " of " + std::to_string(pending) + " " + which + " directions solved (" +
                 std::to_string(basis_.size()) + " in all)");
  });
}

Eigen::VectorXd ControlledGlobalStage::loosenings(const Eigen::MatrixXd& c_new, double w_norm) const {
  Eigen::VectorXd out = Eigen::VectorXd::Ones(c_new.rows());
  if (target_ < 0.0 || !(w_norm > 0.0)) return out;  // no gap known yet
  const double gap = target_ / options_.gap_share;
  for (Eigen::Index j = 0; j < out.size(); ++j)
    out[j] = std::clamp(w_norm / (c_new.row(j).norm() + gap), 1.0, options_.loosening_cap);
  return out;
}

double ControlledGlobalStage::enrich(Eigen::MatrixXd& c, Eigen::MatrixXd& r_scaled, double error, double target,
                                     double w_norm) {
  const Eigen::VectorXd& sqrt_k = basis_.sqrtK();
  std::vector<double> loosening;
  while (error > target && basis_.size() < basis_.maxSize()) {
    const int room = std::min(options_.block, basis_.maxSize() - basis_.size());
    const Eigen::MatrixXd found = leadingDirections(r_scaled, error, target, room, options_, passes_++);
    const int before = basis_.size();
    if (found.cols() == 0 || basis_.appendDirections(sqrt_k.asDiagonal() * found) == 0) break;
    // New directions are k⁻¹-orthogonal to the old ones: their coordinates come from r alone.
    const int added = basis_.size() - before;
    const auto scaled_new = basis_.scaledDirections().rightCols(added);
    const Eigen::MatrixXd c_new = scaled_new.transpose() * r_scaled;
    c.conservativeResize(basis_.size(), Eigen::NoChange);
    c.bottomRows(added) = c_new;
    r_scaled.noalias() -= scaled_new * c_new;
    error = r_scaled.norm();
    const Eigen::VectorXd added_loosening = loosenings(c_new, w_norm);
    loosening.insert(loosening.end(), added_loosening.begin(), added_loosening.end());
  }
  solvePendingNoted(Eigen::Map<const Eigen::VectorXd>(loosening.data(), static_cast<Eigen::Index>(loosening.size())),
                    "new");
  return error;
}

void ControlledGlobalStage::writeScaledRightHandSides(const InterfaceHistory& hat, Eigen::Ref<Eigen::MatrixXd> out) const {
  const Eigen::VectorXd& k = problem_.contact.search_direction;
  out = basis_.invSqrtK().asDiagonal() * (hat.lambda + k.asDiagonal() * hat.v);
}

Eigen::MatrixXd ControlledGlobalStage::scaledRightHandSides(const InterfaceHistory& hat) const {
  Eigen::MatrixXd w(hat.v.rows(), hat.v.cols());
  writeScaledRightHandSides(hat, w);
  return w;
}

void ControlledGlobalStage::completeWhenDue() {
  if (every_row_ || !basis_.condensesInterface() || basis_.size() < options_.full_share * basis_.maxSize()) return;
  basis_.completeToEveryRow();
  every_row_ = true;
}

const Eigen::MatrixXd& ControlledGlobalStage::coordinates() const {
  if (c_stale_) {
    c_.noalias() = basis_.scaledDirections().transpose() * w_last_;
    c_stale_ = false;
  }
  return c_;
}

double ControlledGlobalStage::project(const Eigen::MatrixXd& w_scaled, Eigen::MatrixXd& c, Eigen::MatrixXd& r_scaled) {
  const Eigen::MatrixXd& scaled = basis_.scaledDirections();
  c.noalias() = scaled.transpose() * w_scaled;
  r_scaled = w_scaled;
  r_scaled.noalias() -= scaled * c;
  // Before any gap is known (the first solve, or a warm start) the bound is a share of w itself.
  const double target = target_ >= 0.0 ? target_ : options_.gap_share * w_scaled.norm();
  return enrich(c, r_scaled, r_scaled.norm(), target, w_scaled.norm());
}

Eigen::MatrixXd ControlledGlobalStage::anticipate(const InterfaceHistory& hat) {
  completeWhenDue();
  Eigen::MatrixXd c, r_scaled;
  if (every_row_)  // Zs is square and orthogonal: nothing is left to enrich along
    c.noalias() = basis_.scaledDirections().transpose() * scaledRightHandSides(hat);
  else
    project(scaledRightHandSides(hat), c, r_scaled);
  return c;
}

Eigen::MatrixXd ControlledGlobalStage::stepSketch(Eigen::Index instants, int samples) {
  return linalg::gaussianSketch(instants, samples, 20261129u) / std::sqrt(static_cast<double>(samples));
}

ControlledGlobalStage::Anticipated ControlledGlobalStage::anticipateWhitened(const InterfaceHistory& hat,
                                                                             int step_samples) {
  completeWhenDue();
  Anticipated out;
  if (!every_row_) {
    const Eigen::MatrixXd c = anticipate(hat);  // may enrich: the factor is read after it
    out.whitened = whitenedHistory(basis_, c);
    if (step_samples > 0 && c_.size() > 0 && c_.cols() == c.cols()) {
      // R [0; (c − c_last) Ω]: the load histories G are the same in both.
      Eigen::MatrixXd dc = c;
      dc.topRows(c_.rows()) -= c_;
      Eigen::MatrixXd theta = Eigen::MatrixXd::Zero(basis_.loadHistories().rows() + dc.rows(), step_samples);
      theta.bottomRows(dc.rows()).noalias() = dc * stepSketch(c.cols(), step_samples);
      out.step = basis_.energyFactor().whiten(theta);
    }
    return out;
  }
  const EnergyFactor& factor = basis_.energyFactor();
  const Eigen::Index q = basis_.loadHistories().rows();
  if (whitened_rows_.size() == 0)
    whitened_rows_.noalias() = factor.coordinatesOfColumns().rightCols(basis_.size()) * basis_.scaledDirections().transpose();
  out.whitened = factor.coordinatesOfColumns().leftCols(q) * basis_.loadHistories();
  // w̃ and the step's columns in buffers kept from call to call (header: no fresh pages per relaxation).
  const Eigen::Index m = hat.v.cols();
  const bool with_step = step_samples > 0 && w_last_.rows() == hat.v.rows() && w_last_.cols() == m;
  Eigen::MatrixXd& both = buffers_.anticipated;
  both.resize(hat.v.rows(), m + (with_step ? step_samples : 0));
  writeScaledRightHandSides(hat, both.leftCols(m));
  if (!with_step) {
    linalg::multiplyAdd(whitened_rows_, both, out.whitened);
    return out;
  }
  // One product for the history and the step: R_Z Z̃ᵀ [w̃, (w̃ − w̃_last) Ω].
  both.rightCols(step_samples).noalias() = (both.leftCols(m) - w_last_) * stepSketch(m, step_samples);
  linalg::multiply(whitened_rows_, both, buffers_.product);
  out.whitened += buffers_.product.leftCols(m);
  out.step = buffers_.product.rightCols(step_samples);
  return out;
}

namespace {
// body(first, count) over ranges of columns of a rows × m field, on the threads when it is large
// (threadsForField); each entry's arithmetic is that of the whole-field expression (elementwise), so
// the bits are too.
template <class Body>
void overColumnRanges(Eigen::Index rows, Eigen::Index m, Body&& body) {
  parallelRanges(static_cast<int>(m), threadsForField(rows * m), [&](int begin, int end) { body(begin, end - begin); });
}
}  // namespace

void ControlledGlobalStage::solveEveryRow(const InterfaceHistory& hat, InterfaceHistory& s) {
  // The exact stage v = V_F G + D w, λ = w − k v (header, "Every row"), its passes over the
  // history in two threaded sweeps around the product.
  const Eigen::VectorXd& k = problem_.contact.search_direction;
  const Eigen::VectorXd& inv_sqrt_k = basis_.invSqrtK();
  const Eigen::MatrixXd& free_response = basis_.freeResponse();
  const Eigen::Index rows = hat.v.rows(), m = hat.v.cols();
  Eigen::MatrixXd& w = buffers_.solved;
  w.resize(rows, m);
  s.v.resize(rows, m);
  s.lambda.resize(rows, m);
  w_last_.resize(rows, m);
  overColumnRanges(rows, m, [&](Eigen::Index first, Eigen::Index count) {
    w.middleCols(first, count) = hat.lambda.middleCols(first, count) + k.asDiagonal() * hat.v.middleCols(first, count);
    s.v.middleCols(first, count) = free_response.middleCols(first, count);
  });
  linalg::multiplyAdd(basis_.condensedInterface(), w, s.v);
  overColumnRanges(rows, m, [&](Eigen::Index first, Eigen::Index count) {
    s.lambda.middleCols(first, count) = w.middleCols(first, count) - k.asDiagonal() * s.v.middleCols(first, count);
    w_last_.middleCols(first, count) = inv_sqrt_k.asDiagonal() * w.middleCols(first, count);
  });
  c_stale_ = true;
  error_ = 0.0;
}

void ControlledGlobalStage::solve(const InterfaceHistory& hat, InterfaceHistory& s) {
  const Eigen::VectorXd& k = problem_.contact.search_direction;
  completeWhenDue();
  if (every_row_) {
    solveEveryRow(hat, s);
    return;
  }
  // Scaled right-hand sides w̃ = k^{-1/2} (λ̂ + k v̂) and their projection on the directions.
  const Eigen::MatrixXd w_scaled = scaledRightHandSides(hat);
  Eigen::MatrixXd r_scaled;
  error_ = project(w_scaled, c_, r_scaled);
  s.v = basis_.freeResponse();
  s.v.noalias() += basis_.traces() * c_;
  // λ = Z c − k v with Z c = k^{1/2} (w̃ − r̃).
  s.lambda = basis_.sqrtK().asDiagonal() * (w_scaled - r_scaled);
  s.lambda -= k.asDiagonal() * s.v;
}

}  // namespace stc::pgd
