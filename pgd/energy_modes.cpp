#include "pgd/energy_modes.hpp"

#include <cmath>

namespace stc::pgd {

EnergyModes::EnergyModes(const Eigen::SparseMatrix<double>& A, const Eigen::SparseMatrix<double>& B,
                         Eigen::MatrixXd F)
    : A_(A),
      B_(B),
      loads_(std::move(F)),
      modes_(A.rows(), 0),
      interface_(B.rows(), 0),
      load_projection_(0, loads_.cols()) {}

bool EnergyModes::add(Eigen::VectorXd mode, double drop) {
  Eigen::VectorXd Amode = A_ * mode;
  const double original = std::sqrt(std::max(0.0, mode.dot(Amode)));
  if (!(original > 0.0) || !std::isfinite(original)) return false;
  for (int pass = 0; pass < 2 && rank() > 0; ++pass) {  // classical Gram–Schmidt, reorthogonalised
    const Eigen::VectorXd c = modes_.transpose() * Amode;
    mode.noalias() -= modes_ * c;
    Amode = A_ * mode;
  }
  const double norm = std::sqrt(std::max(0.0, mode.dot(Amode)));
  if (!(norm > drop * original)) return false;
  mode /= norm;
  const Eigen::Index r = rank();
  modes_.conservativeResize(Eigen::NoChange, r + 1);
  modes_.col(r) = mode;
  interface_.conservativeResize(Eigen::NoChange, r + 1);
  interface_.col(r) = B_ * mode;
  load_projection_.conservativeResize(r + 1, Eigen::NoChange);
  load_projection_.row(r) = mode.transpose() * loads_;
  return true;
}

double EnergyModes::orthonormalityDefect() const {
  if (rank() == 0) return 0.0;
  const Eigen::MatrixXd G = modes_.transpose() * (A_ * modes_);
  return (G - Eigen::MatrixXd::Identity(rank(), rank())).cwiseAbs().maxCoeff();
}

}  // namespace stc::pgd
