#pragma once
// Solves a sequence of square systems M x = b whose matrices differ from one another in a few rows,
// with one LU factorisation reused across them: the semismooth Newton systems of the incremental
// solver at one instant and from one instant to the next (src/incremental/cone_newton.cpp), where
// only the rows of the slipping nodes' tangential parts change while the closed set stays.
//
// With M₀ = P⁻¹ L U factorised and M = M₀ + Eᵀ D, E selecting the r rows where M differs from M₀
// and D = (M − M₀)(rows, :) (r × n), the Sherman–Morrison–Woodbury formula (Golub & Van Loan,
// Matrix Computations, 4th ed., §2.1.4):
//   M⁻¹ b = y − Z (I_r + D Z)⁻¹ D y,   y = M₀⁻¹ b,  Z = M₀⁻¹ Eᵀ (n × r),
// costs two triangular solves, r² n and r³ flops, and M₀⁻¹'s columns for rows that changed for the
// first time since the factorisation (kept for the next systems), against (2/3) n³ for a new LU.
// A new LU is made when the key (the caller's name for the rows' meaning: the closed set) changes,
// when more than `max_share` of the rows changed, and whenever the updated solution leaves a
// residual ‖b − M x‖₂ above kResidualBound ‖b‖₂ (an ill-conditioned capacitance I_r + D Z): the
// answer is then the new LU's, as without reuse.
#include <Eigen/Core>
#include <Eigen/LU>
#include <vector>

namespace stc::linalg {

class RowUpdatedLu {
 public:
  /// Largest relative residual accepted from an update: about what a partial-pivot LU leaves on
  /// the Newton systems (10⁻¹⁵ to 10⁻¹³), with room for the capacitance's round-off.
  static constexpr double kResidualBound = 1e-11;

  /// `max_share`: the largest share of rows that may differ from the factorised matrix.
  explicit RowUpdatedLu(double max_share = 0.5);

  /// x with M x = b. `key` names the meaning of M's rows; a different key than the factorised
  /// matrix's (or a different size) makes a new LU.
  Eigen::VectorXd solve(const std::vector<int>& key, const Eigen::MatrixXd& M, const Eigen::VectorXd& b);
  /// The same for an M that differs from the previous call's M in the rows `changed` at most (the
  /// caller's promise: the Newton systems, whose rows change with their node's law): the rows that
  /// differ from the factorised matrix are sought among those and the ones that differed at the
  /// previous call, in O(that many rows · n) instead of the whole comparison's n². The same rows
  /// are found, so x is the same bit for bit.
  Eigen::VectorXd solve(const std::vector<int>& key, const Eigen::MatrixXd& M, const Eigen::VectorXd& b,
                        const std::vector<Eigen::Index>& changed);

  struct Counts {
    long factorisations = 0;  ///< LU of a new matrix
    long updates = 0;         ///< solves through the update formula
    long rejected = 0;        ///< updates whose residual exceeded the bound (then factorised)
  };
  const Counts& counts() const { return counts_; }

 private:
  static void requireSizes(const Eigen::MatrixXd& M, const Eigen::VectorXd& b);  ///< throws std::invalid_argument
  /// Whether M may be solved through the factor held: one is, of the same key and size.
  bool updatable(const std::vector<int>& key, const Eigen::MatrixXd& M) const;
  Eigen::VectorXd factorise(const std::vector<int>& key, const Eigen::MatrixXd& M, const Eigen::VectorXd& b);
  /// Whether M x = b was solved through the update of M₀'s factor, with `rows` those where M
  /// differs from M₀ (ascending).
  bool update(const Eigen::MatrixXd& M, const Eigen::VectorXd& b, const std::vector<Eigen::Index>& rows,
              Eigen::VectorXd& x);
  std::vector<Eigen::Index> changedRows(const Eigen::MatrixXd& M) const;
  /// changedRows(M) when M differs from the previous call's M in `changed` at most.
  std::vector<Eigen::Index> changedRowsAmong(const Eigen::MatrixXd& M, const std::vector<Eigen::Index>& changed) const;
  void ensureColumns(const std::vector<Eigen::Index>& rows);

  double max_share_;
  std::vector<int> key_;
  Eigen::MatrixXd M0_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  bool factorised_ = false;
  Eigen::MatrixXd columns_;              // M₀⁻¹ e_j for the rows j of column_of_, in that order
  std::vector<Eigen::Index> column_of_;  // per row of M₀, its column in columns_ (−1: not yet)
  std::vector<Eigen::Index> differing_;  // the rows where the previous call's M differed from M₀
  Eigen::Index stored_ = 0;
  Counts counts_;
};

}  // namespace stc::linalg
