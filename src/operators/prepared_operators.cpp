#include "stcontact/operators/prepared_operators.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "stcontact/core/clock.hpp"
#include "stcontact/linalg/prepare_spd_solver.hpp"
#include "stcontact/operators/rigid_body_modes.hpp"

namespace stc {
namespace {

using Clock = std::chrono::steady_clock;

// FNV-1a over the bytes of `count` values at `data`.
template <class T>
std::uint64_t hashBytes(std::uint64_t h, const T* data, Eigen::Index count) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < static_cast<std::size_t>(count) * sizeof(T); ++i) {
    h ^= bytes[i];
    h *= 1099511628211ull;
  }
  return h;
}

// A fingerprint of a compressed sparse matrix: its size, pattern and values. Two copies of one
// problem's K_ff (a problem restricted to some contact nodes keeps its body) have the same.
std::uint64_t fingerprint(const Eigen::SparseMatrix<double>& A) {
  if (!A.isCompressed()) throw std::logic_error("PreparedOperators: K_ff must be compressed");
  std::uint64_t h = 14695981039346656037ull;
  const Eigen::Index sizes[] = {A.rows(), A.cols(), A.nonZeros()};
  h = hashBytes(h, sizes, 3);
  h = hashBytes(h, A.outerIndexPtr(), A.outerSize() + 1);
  h = hashBytes(h, A.innerIndexPtr(), A.nonZeros());
  return hashBytes(h, A.valuePtr(), A.nonZeros());
}

bool sameEntries(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros()) return false;
  const auto n = static_cast<std::size_t>(a.nonZeros());
  return std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + n, b.innerIndexPtr()) &&
         std::equal(a.valuePtr(), a.valuePtr() + n, b.valuePtr());
}

// What the backend may use: the dofs to order last, and the rigid-body motions for an AMG (formed
// only when one is prepared).
SpdSolverHints hintsFor(const Problem& problem, const Ordering& ordering) {
  return {ordering.trailing, ordering.min_work, [&problem] { return rigidBodyModesOfFreeDofs(problem); }};
}

}  // namespace

PreparedOperators::PreparedOperators(LinearSolverOptions linear) : linear_(linear) {}

Eigen::SparseMatrix<double> searchDirectionOperator(const Problem& problem) {
  const auto& B = problem.contact.B;
  const Eigen::SparseMatrix<double> kB = problem.contact.search_direction.asDiagonal() * B;
  return Eigen::SparseMatrix<double>(problem.stiffness_free + Eigen::SparseMatrix<double>(B.transpose()) * kB);
}

std::shared_ptr<const SpdSolver> PreparedOperators::stiffnessFree(const Problem& problem, const Ordering& ordering) {
  const std::uint64_t print = fingerprint(problem.stiffness_free);
  const std::lock_guard<std::mutex> lock(mutex_);
  if (stiffness_free_) {
    if (print != stiffness_fingerprint_)
      throw std::invalid_argument("PreparedOperators: another K_ff than the one prepared (one owner per body)");
    ++records_[stiffness_record_].uses;
    return stiffness_free_;
  }
  const auto start = Clock::now();
  stiffness_free_ = prepareSpdSolver(problem.stiffness_free, "the free-dof stiffness K_ff", linear_,
                                     hintsFor(problem, ordering));
  stiffness_fingerprint_ = print;
  Preparation record{"K_ff", stiffness_free_->backend(), problem.numFreeDofs(), 0, stiffness_free_->factorNonZeros(),
                     secondsSince(start), 1, !stiffness_free_->isDirect(), {}};
  records_.push_back(record);
  stiffness_record_ = records_.size() - 1;
  return stiffness_free_;
}

std::shared_ptr<const SearchOperator> PreparedOperators::searchOperator(const Problem& problem,
                                                                        const Ordering& ordering) {
  Eigen::SparseMatrix<double> matrix = searchDirectionOperator(problem);
  const std::lock_guard<std::mutex> lock(mutex_);
  for (Search& s : search_)
    if (s.ordering == ordering && sameEntries(s.op->matrix, matrix)) {
      ++records_[s.record].uses;
      return s.op;
    }
  const auto start = Clock::now();
  std::unique_ptr<SpdSolver> factor =
      prepareSpdSolver(matrix, "K + B^T k B", linear_, hintsFor(problem, ordering));
  auto op = std::make_shared<const SearchOperator>(SearchOperator{std::move(matrix), std::move(factor)});
  records_.push_back({"K_ff + B^T k B", op->factor->backend(), problem.numFreeDofs(), problem.contact.size(),
                      op->factor->factorNonZeros(), secondsSince(start), 1, !op->factor->isDirect(), {}});
  search_.push_back({ordering, op, records_.size() - 1});
  return op;
}

std::vector<Preparation> PreparedOperators::preparations() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::vector<Preparation> out = records_;
  if (stiffness_free_) out[stiffness_record_].krylov = stiffness_free_->krylovCounts();
  for (const Search& s : search_) out[s.record].krylov = s.op->factor->krylovCounts();
  return out;
}

long long PreparedOperators::krylovIterations() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  long long total = stiffness_free_ ? stiffness_free_->krylovCounts().iterations : 0;
  for (const Search& s : search_) total += s.op->factor->krylovCounts().iterations;
  return total;
}

PreparedOperators& operatorsOr(PreparedOperators* operators, std::unique_ptr<PreparedOperators>& own) {
  if (operators) return *operators;
  if (!own) own = std::make_unique<PreparedOperators>();
  return *own;
}

}  // namespace stc
