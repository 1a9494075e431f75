#include "stcontact/latin/global_stage.hpp"

#include <algorithm>

#include "stcontact/core/threads.hpp"

namespace stc::latin {

// An owner of its own, which the stage outlives: the operator stays with the stage's shared pointer.
GlobalStage::GlobalStage(const Problem& problem, int block_size)
    : GlobalStage(problem, *std::make_unique<PreparedOperators>(), block_size) {}

GlobalStage::GlobalStage(const Problem& problem, PreparedOperators& operators, int block_size)
    : problem_(problem),
      operator_(operators.searchOperator(problem)),
      B_rows_(problem.contact.B),
      block_size_(std::max(1, block_size)) {}

void GlobalStage::solve(const InterfaceHistory& hat, InterfaceHistory& s, Eigen::MatrixXd* u_out) {
  const int m = hat.numSteps();
  s.v.resize(hat.v.rows(), m);
  s.lambda.resize(hat.lambda.rows(), m);
  if (u_out) u_out->resize(problem_.numFreeDofs(), m);
  const int blocks = (m + block_size_ - 1) / block_size_;
  const int threads = std::min(threadCount(), blocks);
  while (static_cast<int>(workspaces_.size()) < threads) workspaces_.emplace_back();
  parallelFor(blocks, threads, [&](int block, int thread) {
    const int k0 = block * block_size_;
    solveBlock(k0, std::min(block_size_, m - k0), hat, s, u_out, workspaces_[thread]);
  });
  sparse_solves_ += m;
}

// Writes only the block's columns of s and u: blocks never share a column.
void GlobalStage::solveBlock(int k0, int count, const InterfaceHistory& hat, InterfaceHistory& s,
                             Eigen::MatrixXd* u_out, SpdSolver::Workspace& workspace) const {
  const auto& B = problem_.contact.B;
  const Eigen::VectorXd& k = problem_.contact.search_direction;
  const auto v_hat = hat.v.middleCols(k0, count);
  const auto l_hat = hat.lambda.middleCols(k0, count);
  Eigen::MatrixXd rhs = problem_.loadBlock(k0, count);
  rhs.noalias() += B.transpose() * (l_hat + k.asDiagonal() * v_hat);
  const Eigen::MatrixXd u = operator_->factor->solve(rhs, workspace);
  s.v.middleCols(k0, count).noalias() = B_rows_ * u;
  s.lambda.middleCols(k0, count) = l_hat - k.asDiagonal() * (s.v.middleCols(k0, count) - v_hat);
  if (u_out) u_out->middleCols(k0, count) = u;
}

}  // namespace stc::latin
