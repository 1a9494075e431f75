#pragma once
// Anderson acceleration of a fixed-point iteration x ← F(x) (Anderson 1965; the "type II" form of
// Walker & Ni, SIAM J. Numer. Anal. 49, 2011, eq. (2.2) with mixing β = 1). With the residuals
// f_j = F(x_j) − x_j and the differences of the last `depth` residuals and images,
//   ΔF = [f_{i+1} − f_i],  ΔG = [F(x_{i+1}) − F(x_i)]   (i = j − depth … j − 1),
//   γ = argmin ‖f_j − ΔF γ‖,   x_{j+1} = F(x_j) − ΔG γ,
// the combination of the last depth + 1 images whose combined residual is smallest. On a linear
// contraction it is a Krylov method (GMRES-equivalent, Walker & Ni §4); on LATIN's nonsmooth maps
// it is a heuristic, so it restarts: when a mixed iterate's residual exceeds its predecessor's, the
// differences are forgotten and the step is the plain one (the safeguard of Zhang, O'Donoghue &
// Boyd, SIAM J. Sci. Comput. 42, 2020, in its simplest form).
// The iterates are matrices (an interface history: rows × instants) and the least-squares norm is
// weighted by row, ‖diag(w) f‖_F. γ comes from the normal equations of the depth × depth Gram
// matrix of ΔF, updated by one column per call, with a relative Tikhonov shift of 1e-12 (Walker &
// Ni §5 solve the same small problem; depth ≤ 10 keeps it well away from round-off trouble).
// Memory: 2 depth + 2 iterates (ΔF by slot, f_{j−1}, the last depth + 1 images: ΔG is formed from
// them); per call two passes over the columns, each split over threadCount() threads (the sums are
// taken per column and added in column order: the result does not depend on the split).
#include <Eigen/Core>
#include <vector>

namespace stc {

class AndersonMixing {
 public:
  /// `depth` >= 1: differences kept; `row_weights`: w, one per row of the iterates (> 0).
  AndersonMixing(int depth, Eigen::VectorXd row_weights);

  /// Given x_j (in `x`) and F(x_j), overwrites `x` with x_{j+1} (F(x_j) on the first call).
  void next(Eigen::MatrixXd& x, const Eigen::MatrixXd& image);
  /// As next, without copying F(x_j): the mixing keeps the storage of `image` and hands back in it
  /// a buffer of the same size whose contents are unspecified (the caller overwrites it).
  void nextTaking(Eigen::MatrixXd& x, Eigen::MatrixXd& image);
  /// Restarts so far: mixed iterates whose residual exceeded their predecessor's.
  int restarts() const { return restarts_; }

 private:
  void requireSizes(const Eigen::MatrixXd& x, const Eigen::MatrixXd& image) const;  ///< throws std::invalid_argument
  /// One step from x_j, F(x_j) being in the ring already: x ← x_{j+1}.
  void advance(Eigen::MatrixXd& x);
  /// The first pass over the columns: f_j and ΔF_new stored, ⟨ΔF_new, ΔF_a⟩ into `row` and
  /// ⟨ΔF_a, f_j⟩ into `rhs` for the `held` slots. Returns ‖f_j‖² (weighted).
  double updateDifferences(const Eigen::MatrixXd& x, int held, Eigen::VectorXd& row, Eigen::VectorXd& rhs);
  /// The second pass: x = F(x_j) − ΔG γ.
  void mix(Eigen::MatrixXd& x, const Eigen::VectorXd& gamma);
  /// F(x_t), kept for the last depth + 1 calls (t ≥ call_ − depth).
  Eigen::MatrixXd& imageOf(long t) { return images_[static_cast<size_t>(t % (depth_ + 1))]; }

  int depth_, count_ = 0;  ///< differences held, at most depth_
  int newest_ = -1;        ///< slot of the newest difference (a ring of depth_ slots)
  long call_ = -1;         ///< calls so far, less one: j
  Eigen::VectorXd w_;
  Eigen::MatrixXd last_f_;  ///< weighted f_{j−1}
  double last_norm_ = 0.0;  ///< ‖f_{j−1}‖ (weighted)
  bool mixed_ = false;      ///< x_j came from a mixed step
  int restarts_ = 0;
  std::vector<Eigen::MatrixXd> df_;      ///< weighted ΔF, by slot
  std::vector<long> slot_call_;          ///< the call t whose differences fill each slot
  std::vector<Eigen::MatrixXd> images_;  ///< F(x_t), a ring of depth_ + 1 (ΔG is formed from it)
  Eigen::MatrixXd gram_;                 ///< ⟨ΔF_a, ΔF_b⟩ by slot
};

}  // namespace stc
