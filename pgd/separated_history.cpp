#include "stcontact/pgd/separated_history.hpp"

#include <algorithm>
#include <map>

#include "stcontact/linalg/dense_decompositions.hpp"

namespace stc::pgd {
namespace {

constexpr int kOversampling = 10;
constexpr int kSubspaceIterations = 2;
constexpr Eigen::Index kSmallSvdRows = 64;  ///< leadingSingularVectors: QR iteration (Jacobi without OpenBLAS) up to this many samples

constexpr unsigned kSketchSeed = 20160101u;

// The range finder's sketch Ω (rows × cols): the same seed on every call, so the same matrix for a
// given size. Drawing it cost about a fifth of the coarse space on the seed scene (std::normal
// draws, two calls per coarse step), so it is drawn once per row count (per thread) at the widest
// width asked: filled column by column, a narrower sketch is its leading columns, the same numbers
// as a fresh draw.
Eigen::Ref<const Eigen::MatrixXd> fixedSketch(Eigen::Index rows, Eigen::Index cols) {
  thread_local std::map<Eigen::Index, Eigen::MatrixXd> sketches;
  Eigen::MatrixXd& sketch = sketches[rows];
  if (sketch.cols() < cols) sketch = linalg::gaussianSketch(rows, cols, kSketchSeed);
  return sketch.leftCols(cols);
}

// An orthonormal basis of (approximately) the leading `samples`-dimensional range of C.
Eigen::MatrixXd rangeFinder(const Eigen::MatrixXd& C, Eigen::Index samples) {
  if (samples == C.rows()) return Eigen::MatrixXd::Identity(C.rows(), C.rows());
  return linalg::randomizedRange(C, fixedSketch(C.cols(), samples), kSubspaceIterations);
}

}  // namespace

Eigen::MatrixXd historyFactor(const ResponseBasis& basis, const Eigen::MatrixXd& c) {
  const Eigen::MatrixXd& G = basis.loadHistories();
  Eigen::MatrixXd theta = Eigen::MatrixXd::Zero(G.rows() + basis.size(), G.cols());
  theta.topRows(G.rows()) = G;
  theta.middleRows(G.rows(), c.rows()) = c;
  return theta;
}

Eigen::MatrixXd whitenedHistory(const ResponseBasis& basis, const Eigen::MatrixXd& c) {
  return basis.energyFactor().whiten(historyFactor(basis, c));
}

Eigen::MatrixXd leadingSingularVectors(const Eigen::MatrixXd& coordinates, int count, double drop) {
  const Eigen::Index samples = std::min<Eigen::Index>({count + kOversampling, coordinates.rows(), coordinates.cols()});
  if (count <= 0 || samples == 0) return Eigen::MatrixXd(coordinates.rows(), 0);
  const Eigen::MatrixXd Q = rangeFinder(coordinates, samples);
  // The SVD of the small projected matrix itself (not of its Gram matrix, whose eigenvalues would resolve σ only
  // down to √ε σ_1): singular values to ε σ_1, so `drop` means what it says. For the coarse spaces' at most
  // 40 rows LAPACK's QR iteration on the transpose (Jacobi without OpenBLAS: on the seed scene it took 26–38 ms
  // over 77 calls against 36–41 ms for divide and conquer); divide and conquer above kSmallSvdRows rows
  // (energyModes at the end of a solve asks for every mode: at 1601 contact nodes Jacobi took 4 % of the solve).
  const linalg::SvdMethod method =
      samples <= kSmallSvdRows ? linalg::SvdMethod::qr_iteration : linalg::SvdMethod::divide_and_conquer;
  const linalg::Svd svd = linalg::singularValueDecomposition(Q.transpose() * coordinates, method, linalg::kThinU);
  const Eigen::VectorXd& sigma = svd.values;  // decreasing
  int keep = 0;
  while (keep < count && keep < sigma.size() && sigma[keep] > drop * sigma[0]) ++keep;
  return Q * svd.U.leftCols(keep);
}

EnergySvd energySvd(const ResponseBasis& basis, const Eigen::MatrixXd& c, int count, double drop) {
  const EnergyFactor& factor = basis.energyFactor();
  const Eigen::MatrixXd coordinates = whitenedHistory(basis, c);
  const Eigen::MatrixXd U = leadingSingularVectors(coordinates, count, drop);
  EnergySvd svd;
  svd.combination = factor.combination(U);
  svd.time_functions = U.transpose() * coordinates;
  svd.singular_values = svd.time_functions.rowwise().norm();
  return svd;
}

Eigen::MatrixXd spatialModes(const ResponseBasis& basis, const Eigen::MatrixXd& combination) {
  const Eigen::Index q = basis.loadResponses().cols();
  Eigen::MatrixXd Y = basis.loadResponses() * combination.topRows(q);
  if (!basis.holdsResponses())  // released beyond their bytes: the modes' own solves
    Y += basis.responsesOf(combination.bottomRows(combination.rows() - q));
  else
    basis.responses().addProduct(combination.bottomRows(combination.rows() - q), Y);
  return Y;
}

Eigen::MatrixXd modeTraces(const ResponseBasis& basis, const Eigen::MatrixXd& combination) {
  const Eigen::Index q = basis.loadTraces().cols();
  Eigen::MatrixXd BY = basis.loadTraces() * combination.topRows(q);
  BY.noalias() += basis.traces() * combination.bottomRows(combination.rows() - q);
  return BY;
}

Eigen::Index modesWithinBudget(const Eigen::VectorXd& singular_values, double energy_budget) {
  Eigen::Index rho = singular_values.size();
  for (double tail = 0.0; rho > 0 && tail + singular_values[rho - 1] * singular_values[rho - 1] <= energy_budget; --rho)
    tail += singular_values[rho - 1] * singular_values[rho - 1];
  return rho;
}

double truncationBudget(const SolveSummary& summary, double tolerance) {
  if (!summary.converged() || summary.history.empty()) return 0.0;
  const IterationRecord& last = summary.history.back();
  if (!last.energy || !(last.error_estimate < tolerance)) return 0.0;
  const double slack = tolerance - last.error_estimate;
  return slack * slack * *last.energy;
}

SeparatedDisplacement separatedDisplacement(const ResponseBasis& basis, const Eigen::MatrixXd& c, double energy_budget) {
  const Eigen::Index q = basis.loadResponses().cols();
  const EnergySvd svd = energySvd(basis, c, static_cast<int>(q) + basis.size());
  const Eigen::Index rho = modesWithinBudget(svd.singular_values, energy_budget);
  const Eigen::MatrixXd C = svd.combination.leftCols(rho);
  SeparatedDisplacement out;
  out.held = true;
  out.modes = basis.loadResponses() * C.topRows(q);
  if (C.rows() > q) out.modes += basis.responsesOf(C.bottomRows(C.rows() - q));
  out.time = svd.time_functions.topRows(rho);
  return out;
}

Eigen::MatrixXd energyModes(const ResponseBasis& basis, const Eigen::MatrixXd& c) {
  const int all = static_cast<int>(basis.loadResponses().cols()) + basis.size();
  return spatialModes(basis, energySvd(basis, c, all).combination);
}

}  // namespace stc::pgd
