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
// Memory: 2 depth + 2 iterates; cost per call: 2 depth + 5 passes over an iterate.
#include <Eigen/Core>
#include <vector>

namespace stc {

class AndersonMixing {
 public:
  /// `depth` >= 1: differences kept; `row_weights`: w, one per row of the iterates (> 0).
  AndersonMixing(int depth, Eigen::VectorXd row_weights);

  /// Given x_j (in `x`) and F(x_j), overwrites `x` with x_{j+1} (F(x_j) on the first call).
  void next(Eigen::MatrixXd& x, const Eigen::MatrixXd& image);
  /// Restarts so far: mixed iterates whose residual exceeded their predecessor's.
  int restarts() const { return restarts_; }

 private:
  int depth_, count_ = 0;  ///< differences held, at most depth_
  int newest_ = -1;        ///< slot of the newest difference (a ring of depth_ slots)
  Eigen::VectorXd w_;
  Eigen::MatrixXd last_f_, last_image_;  ///< weighted f_{j−1}, F(x_{j−1}); empty before the first call
  double last_norm_ = 0.0;               ///< ‖f_{j−1}‖ (weighted)
  bool mixed_ = false;                   ///< x_j came from a mixed step
  int restarts_ = 0;
  std::vector<Eigen::MatrixXd> df_, dg_; ///< weighted ΔF and ΔG, by slot
  Eigen::MatrixXd gram_;                 ///< ⟨ΔF_a, ΔF_b⟩ by slot
};

}  // namespace stc
