#include "stcontact/pgd/response_basis.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "stcontact/linalg/dense_decompositions.hpp"
#include "stcontact/linalg/dense_product.hpp"
#include "stcontact/linalg/low_rank_solve.hpp"
#include "stcontact/pgd/separated_history.hpp"
#include "stcontact/pgd/separated_loads.hpp"

namespace stc::pgd {
namespace {

constexpr double kReorthogonalise = 0.70710678118654752;  ///< 1/√2: a second Gram–Schmidt pass below it

}  // namespace

ResponseBasis::ResponseBasis(const Problem& problem, const SpdSolver& factor, double response_bytes)
    : problem_(problem),
      factor_(factor),
      Z_(problem.contact.rows()),
      Zs_(problem.contact.rows()),
      T_(problem.contact.rows()),
      X_(problem.numFreeDofs()),
      response_bytes_(response_bytes) {
  if (factor.condenses(problem.contact.B)) condensed_ = factor.condensed(problem.contact.B);
  const Eigen::VectorXd& k = problem.contact.search_direction;
  sqrt_k_ = k.cwiseSqrt();
  inv_sqrt_k_ = sqrt_k_.cwiseInverse();
  const SeparatedLoads loads = separatedLoads(problem);
  G_ = loads.G;
  UF_ = loads.F.cols() > 0 ? factor.solve(loads.F) : Eigen::MatrixXd(problem.numFreeDofs(), 0);
  sparse_solves_ += UF_.cols();
  VF_ = problem.contact.B * UF_;
  v0_ = VF_ * G_;
  // U_Fᵀ A U_F = U_Fᵀ F, symmetrised.
  const Eigen::MatrixXd load_energy = UF_.transpose() * loads.F;
  for (Eigen::Index j = 0; j < UF_.cols(); ++j)
    energy_.append(0.5 * (load_energy.col(j).head(j + 1) + load_energy.row(j).head(j + 1).transpose()));
}

void ResponseBasis::retime(const Problem& grid) {
  bool same = grid.numFreeDofs() == problem_.numFreeDofs() && grid.contact.rows() == problem_.contact.rows() &&
              grid.loads.size() == problem_.loads.size();
  for (size_t i = 0; same && i < grid.loads.size(); ++i)
    same = grid.loads[i].free_force == problem_.loads[i].free_force;
  if (!same) throw std::invalid_argument("ResponseBasis::retime: not the same problem on another time grid");
  G_ = separatedLoads(grid).G;
  v0_ = VF_ * G_;
}

Eigen::MatrixXd ResponseBasis::orthonormalised(const Eigen::MatrixXd& candidates, double drop) const {
  Eigen::MatrixXd Y = inv_sqrt_k_.asDiagonal() * candidates;
  const Eigen::VectorXd original = Y.colwise().norm();
  const View Zs = Zs_.view();
  if (Zs.cols() > 0) {
    Y -= Zs * (Zs.transpose() * Y);
    // A second pass only for the columns that lost more than 1 − 1/√2 of their norm in the first
    // (the criterion of Daniel, Gragg, Kaufman & Stewart, Math. Comp. 30, 1976; with it classical
    // Gram–Schmidt keeps orthogonality to working precision, Giraud, Langou & Rozložník, Comput.
    // Math. Appl. 50, 2005). Candidates from a projection error are orthogonal to Zs already, and
    // skip it: the pass read all p directions twice.
    std::vector<Eigen::Index> again;
    for (Eigen::Index j = 0; j < Y.cols(); ++j)
      if (Y.col(j).norm() < kReorthogonalise * original[j]) again.push_back(j);
    if (!again.empty()) {
      Eigen::MatrixXd part = Y(Eigen::all, again);
      part -= Zs * (Zs.transpose() * part);
      Y(Eigen::all, again) = part;
    }
  }
  Eigen::Index kept = 0;
  const Eigen::Index room = Z_.rows() - Z_.cols();
  for (Eigen::Index j = 0; j < Y.cols() && kept < room; ++j) {
    if (!(original[j] > 0.0)) continue;
    Eigen::VectorXd y = Y.col(j);
    for (int pass = 0; pass < 2 && kept > 0; ++pass) y -= Y.leftCols(kept) * (Y.leftCols(kept).transpose() * y);
    const double norm = y.norm();
    if (!(norm > drop * original[j])) continue;
    Y.col(kept++) = y / norm;
  }
  return Y.leftCols(kept);
}

void ResponseBasis::extendEnergyFactor(Eigen::Index added) {
  // For a new direction z_j: φ_iᵀ A φ_j = (B φ_i)ᵀ z_j, i ≤ j (the factor reads one triangle; the
  // other side, z_iᵀ (B φ_j), agrees to the sparse solves' accuracy and read all of Z again).
  const View Z = Z_.view(), T = T_.view();
  Eigen::MatrixXd products(VF_.cols() + Z.cols(), added);  // (q + p + added) × added
  products << VF_.transpose() * Z.rightCols(added), T.transpose() * Z.rightCols(added);
  energy_.appendBlock(products);
}

Eigen::MatrixXd ResponseBasis::solveInterfaceLoads(const Eigen::MatrixXd& M) const {
  sparse_solves_ += M.cols();
  if (condensesInterface()) return factor_.solveFromTrailing(problem_.contact.B, M);
  return solveColumns(problem_.contact.B.transpose() * M);
}

Eigen::MatrixXd ResponseBasis::solveColumns(const Eigen::MatrixXd& rhs) const {
  // Parts of a fixed width, whatever the thread count: CHOLMOD's solve runs kernels of 1 to 4
  // columns whose rounding differs, so a column must land in the same group on any thread count.
  constexpr int kPart = 4;
  return factor_.solveInParts(rhs, kPart, workspaces_);
}

int ResponseBasis::appendDirections(const Eigen::MatrixXd& candidates, double drop) {
  const Eigen::MatrixXd scaled = orthonormalised(candidates, drop);
  const Eigen::Index added = scaled.cols();
  if (added == 0) return 0;
  Z_.append(sqrt_k_.asDiagonal() * scaled);
  Zs_.append(scaled);
  pending_ += added;
  return static_cast<int>(added);
}

Eigen::MatrixXd ResponseBasis::solveNewResponses(const Eigen::MatrixXd& rhs, const Eigen::VectorXd& loosening,
                                                 const SolveProgress& progress) const {
  // A direct factor's columns in solveColumns' parts whatever is asked (its numbers bit for bit).
  const auto solve = [&](Eigen::Index first, Eigen::Index count) -> Eigen::MatrixXd {
    if (loosening.size() == 0 || factor_.isDirect()) return solveColumns(rhs.middleCols(first, count));
    return factor_.solveLoosened(rhs.middleCols(first, count), loosening.segment(first, count));
  };
  // A direct factor solves the block at once (a block's columns cost it less each; a multiple of its
  // parts would keep CHOLMOD's numbers, not MUMPS's block solves'); an iterative backend solves each
  // column alone, so that parts of it give the same numbers.
  if (!progress || factor_.isDirect()) return solve(0, rhs.cols());
  Eigen::MatrixXd X(rhs.rows(), rhs.cols());
  for (Eigen::Index first = 0; first < rhs.cols(); first += kProgressColumns) {
    const Eigen::Index count = std::min(kProgressColumns, rhs.cols() - first);
    X.middleCols(first, count) = solve(first, count);
    progress(first + count, rhs.cols());
  }
  return X;
}

void ResponseBasis::solvePending(const Eigen::VectorXd& loosening, const SolveProgress& progress) {
  if (loosening.size() != 0 && loosening.size() != pending_)
    throw std::invalid_argument("ResponseBasis::solvePending: one loosening per pending direction");
  if (pending_ == 0) return;
  const Eigen::Index added = pending_;
  if (condensesInterface()) {
    T_.append(condensed_ * Z_.view().rightCols(added));  // T = B A⁻¹ Bᵀ Z = D Z
  } else {
    const Eigen::MatrixXd rhs = problem_.contact.B.transpose() * Z_.view().rightCols(added);
    Eigen::MatrixXd X = solveNewResponses(rhs, loosening, progress);
    sparse_solves_ += added;
    T_.append(problem_.contact.B * X);
    if (kept_rows_.rows() > 0) kept_traces_.append(Eigen::MatrixXd(kept_rows_ * X));
    keepOrRelease(std::move(X));
  }
  pending_ = 0;
  extendEnergyFactor(added);
}

void ResponseBasis::completeToEveryRow() {
  if (!condensesInterface()) throw std::logic_error("ResponseBasis::completeToEveryRow: needs D = B A⁻¹ Bᵀ");
  solvePending();
  const Eigen::Index n = maxSize(), p = size();
  if (p == n) return;
  const Eigen::MatrixXd scaled = linalg::orthonormalComplement(Zs_.view());
  Zs_.append(scaled);
  Z_.append(sqrt_k_.asDiagonal() * scaled);
  pending_ = n - p;
  solvePending();
}

void ResponseBasis::keepOrRelease(Eigen::MatrixXd&& X) {
  if (released_) return;
  const double bytes = X_.bytes() + static_cast<double>(sizeof(double)) * static_cast<double>(X.size());
  if (bytes <= response_bytes_) {
    X_.append(std::move(X));
    return;
  }
  X_ = ColumnBlocks(problem_.numFreeDofs());  // its memory given back
  released_ = true;
}

const ColumnBlocks& ResponseBasis::responses() const {
  if (released_) throw std::logic_error("ResponseBasis::responses: released beyond their bytes (responsesOf solves them)");
  const Eigen::Index solved = X_.cols(), known = Z_.cols() - pending_;
  if (solved < known) X_.append(solveInterfaceLoads(Z_.view().middleCols(solved, known - solved)));
  return X_;
}

Eigen::MatrixXd ResponseBasis::responsesOf(const Eigen::MatrixXd& M) const {
  const Eigen::Index p = M.rows();
  if (X_.cols() >= p) return X_.times(M);
  return solveInterfaceLoads(Z_.view().leftCols(p) * M);
}

Eigen::MatrixXd ResponseBasis::liftedInterface(const Eigen::SparseMatrix<double>& B_rows, const Eigen::MatrixXd& M) const {
  const Eigen::Index p = M.rows();
  if (B_rows.rows() == 0) return Eigen::MatrixXd(0, M.cols());  // no row to lift to: no solve
  if (X_.cols() >= p) return X_.rowsOf(B_rows, p) * M;
  return linalg::solveThroughRank(factor_, B_rows, problem_.contact.B, Z_.view().leftCols(p) * M, sparse_solves_);
}

Eigen::MatrixXd ResponseBasis::displacementOn(const Eigen::SparseMatrix<double>& B_rows, const Eigen::MatrixXd& c) const {
  Eigen::MatrixXd v = linalg::freshProduct(B_rows * UF_, G_);
  if (c.rows() > 0) v += liftedInterface(B_rows, c);
  return v;
}

void ResponseBasis::keepTracesOn(const Eigen::SparseMatrix<double>& B_rows) {
  if (Z_.cols() > 0) throw std::logic_error("ResponseBasis::keepTracesOn: before the first direction");
  if (B_rows.cols() != problem_.numFreeDofs())
    throw std::invalid_argument("ResponseBasis::keepTracesOn: rows of another width than the free dofs");
  if (condensesInterface()) return;
  kept_rows_ = B_rows;
  kept_traces_ = ColumnBlocks(B_rows.rows());
}

Eigen::MatrixXd ResponseBasis::displacementOnKeptRows(const Eigen::MatrixXd& c) const {
  if (!keepsTracesFor(c.rows()))
    throw std::logic_error("ResponseBasis::displacementOnKeptRows: no traces kept on other rows for these directions");
  Eigen::MatrixXd v = linalg::freshProduct(kept_rows_ * UF_, G_);
  if (c.rows() > 0) kept_traces_.addProduct(c, v);
  return v;
}

Eigen::MatrixXd ResponseBasis::displacementOn(const Eigen::SparseMatrix<double>& B_rows, const Eigen::MatrixXd& c,
                                              double energy_budget) const {
  if (!(energy_budget > 0.0) || B_rows.rows() == 0 || c.rows() == 0 || pending_ > 0) return displacementOn(B_rows, c);
  const Eigen::Index q = G_.rows();
  // Only the left vectors (q + p short, m instants long): the SVD of the tall transpose's R forms no
  // Q of m rows, and Σ_ρ V_ρᵀ = U_ρᵀ H, the product with the history itself. Divide and conquer:
  // q + p reaches the zone's rows (915 on the fretting history at divisions 20).
  const Eigen::MatrixXd whitened = whitenedHistory(*this, c);
  const linalg::Svd svd =
      linalg::singularValueDecomposition(whitened, linalg::SvdMethod::lapack_divide_and_conquer, linalg::kThinU);
  const Eigen::Index rho = modesWithinBudget(svd.values, energy_budget);
  if (rho == svd.values.size()) return displacementOn(B_rows, c);
  const Eigen::MatrixXd C = energy_.combination(svd.U.leftCols(rho));  // (q + p) × ρ
  Eigen::MatrixXd time;
  linalg::multiplyTransposed(svd.U.leftCols(rho), whitened, time);
  Eigen::MatrixXd modes = (B_rows * UF_) * C.topRows(q);
  modes += liftedModes(B_rows, C.middleRows(q, c.rows()), svd.values.head(rho));
  return linalg::freshProduct(modes, time);
}

Eigen::MatrixXd ResponseBasis::liftedModes(const Eigen::SparseMatrix<double>& B_rows, const Eigen::MatrixXd& M,
                                           const Eigen::VectorXd& sigma) const {
  if (factor_.isDirect() || X_.cols() >= M.rows()) return liftedInterface(B_rows, M);  // no loosened solve
  // Each kept σ_i > 0 (modesWithinBudget keeps none of zero energy).
  return liftedInterface(B_rows, M * sigma.asDiagonal()) * sigma.cwiseInverse().asDiagonal();
}

int ResponseBasis::append(const Eigen::MatrixXd& candidates, double drop) {
  const int added = appendDirections(candidates, drop);
  solvePending();
  return added;
}

}  // namespace stc::pgd
