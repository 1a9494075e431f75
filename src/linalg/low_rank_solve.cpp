#include "stcontact/linalg/low_rank_solve.hpp"

#include <algorithm>
#include <limits>

#include "stcontact/linalg/dense_decompositions.hpp"
#include "stcontact/linalg/dense_product.hpp"

namespace stc::linalg {

Eigen::MatrixXd solveThroughRank(const SpdSolver& factor, const Eigen::SparseMatrix<double>& C,
                                 const Eigen::SparseMatrix<double>& R, const Eigen::MatrixXd& M, long& solves) {
  if (M.size() == 0) return Eigen::MatrixXd::Zero(C.rows(), M.cols());
  const Svd svd = singularValueDecomposition(M, SvdMethod::divide_and_conquer, kThinU | kThinV);
  const double floor = static_cast<double>(std::max(M.rows(), M.cols())) * std::numeric_limits<double>::epsilon() *
                       svd.values[0];
  Eigen::Index rank = 0;
  while (rank < svd.values.size() && svd.values[rank] > floor) ++rank;
  solves += rank;
  if (rank == 0) return Eigen::MatrixXd::Zero(C.rows(), M.cols());
  const auto U = svd.U.leftCols(rank);
  Eigen::MatrixXd responses;
  if (factor.condenses(R))
    responses = factor.solveFromTrailing(R, U);
  else if (factor.isDirect())
    responses = factor.solveOnThreads(R.transpose() * U);
  else  // mode i to σ_1/σ_i times the relative residual (header)
    responses = factor.solveLoosened(R.transpose() * U, (svd.values[0] / svd.values.head(rank).array()).matrix());
  return freshProduct(C * responses, svd.values.head(rank).asDiagonal() * svd.V.leftCols(rank).transpose());
}

}  // namespace stc::linalg
