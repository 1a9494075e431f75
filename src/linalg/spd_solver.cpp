#include "stcontact/linalg/spd_solver.hpp"

#include <stdexcept>

namespace stc {

SpdSolver::Workspace::Workspace() = default;
SpdSolver::Workspace::~Workspace() = default;
SpdSolver::Workspace::Workspace(Workspace&&) noexcept = default;
SpdSolver::Workspace& SpdSolver::Workspace::operator=(Workspace&&) noexcept = default;

SpdSolver::SpdSolver() = default;
SpdSolver::~SpdSolver() = default;

Eigen::MatrixXd SpdSolver::solve(const Eigen::MatrixXd& B) const { return solve(B, own_); }

Eigen::VectorXd SpdSolver::solve(const Eigen::VectorXd& b) const { return solve(Eigen::MatrixXd(b), own_).col(0); }

Eigen::MatrixXd SpdSolver::solveInParts(const Eigen::MatrixXd& B, int part, std::vector<Workspace>& workspaces) const {
  if (part < 1) throw std::invalid_argument("SpdSolver::solveInParts: part must be >= 1");
  if (workspaces.empty()) workspaces.emplace_back();
  return solve(B, workspaces.front());
}

Eigen::MatrixXd SpdSolver::solveOnThreads(const Eigen::MatrixXd& B) const { return solve(B); }

void SpdSolver::checkLoosening(const Eigen::MatrixXd& B, const Eigen::VectorXd& loosening) {
  if (loosening.size() != B.cols() || !(loosening.array() >= 1.0).all())
    throw std::invalid_argument("SpdSolver::solveLoosened: one loosening of at least 1 per column");
}

Eigen::MatrixXd SpdSolver::solveLoosened(const Eigen::MatrixXd& B, const Eigen::VectorXd& loosening) const {
  checkLoosening(B, loosening);
  return solve(B);
}

bool SpdSolver::condenses(const Eigen::SparseMatrix<double>&) const { return false; }

Eigen::MatrixXd SpdSolver::condensed(const Eigen::SparseMatrix<double>&) const {
  throw std::invalid_argument("SpdSolver::condensed: the " + backend() + " backend holds no condensed operator");
}

Eigen::MatrixXd SpdSolver::solveFromTrailing(const Eigen::SparseMatrix<double>&, const Eigen::MatrixXd&) const {
  throw std::invalid_argument("SpdSolver::solveFromTrailing: the " + backend() + " backend holds no condensed operator");
}

bool SpdSolver::holdsDofs() const { return false; }

Eigen::VectorXd SpdSolver::solveHeld(const Eigen::VectorXd&, const std::vector<int>&, const Eigen::VectorXd&,
                                     const ReplacedRows&) const {
  throw std::invalid_argument("SpdSolver::solveHeld: the " + backend() + " backend does not hold dofs");
}

KrylovCounts SpdSolver::krylovCounts() const { return {}; }

}  // namespace stc
