#pragma once
// A few extreme eigenpairs of a real symmetric operator given only as y = A x, through ARPACK-NG's
// implicitly restarted Lanczos method called through ARPACK-NG's typed C++ interface
// (arpack/arpack.hpp): the reverse-communication routines dsaupd (iteration) and dseupd (Ritz
// vectors), mode 1 (standard problem, BMAT = 'I'), exact shifts.
// Method: Sorensen, SIAM J. Matrix Anal. Appl. 13 (1992); Lehoucq, Sorensen & Yang, "ARPACK Users'
// Guide" (SIAM 1998), §§2–3; the argument and error-code meanings are those of dsaupd.f/dseupd.f.
//
// Used by the a posteriori space-time SVD (docs/method.md §3) on x ↦ Uᵀ K U x, never on a solve path.
// ARPACK keeps its state in Fortran SAVE variables: one computation at a time per process (a mutex
// in compute() serialises concurrent callers; do not call ArpackEigen from inside the operator).
#include <Eigen/Core>
#include <functional>
#include <vector>

namespace stc::pgd {

/// Which end of the spectrum ARPACK looks for (its WHICH argument).
enum class ArpackWhich {
  LargestAlgebraic,   ///< 'LA'
  SmallestAlgebraic,  ///< 'SA'
  LargestMagnitude,   ///< 'LM'
};

struct ArpackOptions {
  /// NEV: how many eigenpairs are wanted; ARPACK requires 0 < NEV < n.
  int eigenvalues = 6;
  /// NCV: Lanczos vectors kept between restarts; 0 picks min(n, 2·NEV + 1), the users' guide's
  /// "NCV ≥ 2·NEV" advice (dsaupd.f remark 4). Must satisfy NEV < NCV ≤ n.
  int subspace = 0;
  /// Ritz value θ is accepted when its error bound ≤ tolerance · max(ε^{2/3}, |θ|) (dsconv.f);
  /// 0 means machine precision (ARPACK substitutes dlamch('EpsMach')).
  double tolerance = 0.0;
  /// IPARAM(3), the cap on implicit restarts: far above the few dozen a well-separated spectrum needs.
  int max_restarts = 3000;
  ArpackWhich which = ArpackWhich::LargestAlgebraic;
  /// Seed of the starting vector (uniform in [−1, 1]), fixed so that runs are reproducible.
  unsigned seed = 2013;

  /// Throws InputError naming the field, its value and the rule broken, for an operator of size n.
  void validate(int n) const;
};

struct ArpackResult {
  /// Converged eigenvalues, ordered from the wanted end: descending for LargestAlgebraic and
  /// LargestMagnitude (by |θ|), ascending for SmallestAlgebraic.
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;        ///< n × NEV, orthonormal columns, in the order of `values`
  int restarts = 0;               ///< IPARAM(3) on exit
  int operator_applications = 0;  ///< IPARAM(9): number of y = A x products
};

/// RAII wrapper: owns the workspaces (RESID, V, WORKD, WORKL, SELECT) and drives the reverse
/// communication loop. Any nonzero INFO/IERR from ARPACK becomes a std::runtime_error whose message
/// carries ARPACK's own meaning of the code.
class ArpackEigen {
 public:
  /// y = A x, with x and y of size n (y is not aliased with x). A must be symmetric.
  using Operator = std::function<void(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y)>;

  /// Validates the options (InputError) and allocates the workspaces for an operator of size n.
  ArpackEigen(int n, ArpackOptions options);

  /// Runs dsaupd to convergence, then dseupd for the Ritz vectors.
  ArpackResult compute(const Operator& op);

  int size() const { return n_; }
  const ArpackOptions& options() const { return options_; }

 private:
  int n_;
  int ncv_;
  ArpackOptions options_;
  double tol_ = 0.0;  ///< TOL passed to dsaupd and dseupd (0 replaced by dlamch('EpsMach'))
  std::vector<double> resid_, v_, workd_, workl_;
  std::vector<int> select_;

  void iterate(const Operator& op, int iparam[11], int ipntr[11]);
  ArpackResult extract(int iparam[11], int ipntr[11]);
};

/// ARPACK's meaning of an INFO code returned by dsaupd ("dsaupd") or dseupd ("dseupd").
const char* arpackMessage(const char* routine, int info);

}  // namespace stc::pgd
