#pragma once
// The incremental solver's whole-body form (IncrementalOptions::form, incremental_solver.hpp): the
// contact law at instant k solved on the displacement of the whole body instead of the condensed
// interface, one sparse solve per active-set iteration and no Delassus column ever formed: the form
// of deal.II's step-41/42 and dolfinx_contact, a primal–dual active-set method (Hintermüller, Ito &
// Kunisch, SIAM J. Optim. 13, 2002: a semismooth Newton method) warm-started from instant k − 1.
//
// Scope: a rigid obstacle whose contact rows each read one free dof, v_r = b_r u_{d_r} (the half-ball
// scenes, whose normal and tangents are axes), without held rows. An iteration at instant k, from
// the active set of the last one (at the instant's start, instant k − 1's), solves for u with
//   open nodes free of force;
//   closed normal rows held at g = 0:           u_{d_n} = −g0_i / b_n;
//   sticking tangential rows held at s = 0:     u_{d_t} = v_t(t_{k−1}) / b_t;
//   slipping nodes' tangential rows replaced by the Newton linearisation of F_t = λ_t − μ λ̂_n ξ̂
//   (cone_newton.hpp) at the last iterate, written in totals (P ξ = 0 makes it homogeneous):
//     (I − q P) λ_t + q ρ_t P s − μ ξ̂ λ_n = 0,   q = μ λ̂_n / |ξ|, P = I − ξ̂ ξ̂ᵀ,
//   with λ = (K_ff u − f(t_k))_{d_r} / b_r and s = b_t u_{d_t} − v_t(t_{k−1}): rows of K_ff combined
//   within one node's pattern, nonsymmetric (GMRES; CG without slip);
// one solve from the last u (SpdSolver::solveHeld). The closed rows' forces are read off the
// equilibrium, λ_r = (K_ff u − f(t_k))_{d_r} / b_r, then the Alart–Curnier residual F of
// cone_newton.hpp is evaluated at (λ, v = B u) with ρ_n = K_ff(d_n, d_n) / b_n² and ρ_t the mean of
// the tangential rows' (a node's own stiffness; any ρ > 0 has the same roots): its pieces give the
// next active set. This is the semismooth Newton method on F with the unknown u (the Newton step of
// a held row is exact in one solve). The instant ends at ‖F‖∞ ≤ tolerance · S_k,
//   S_k = max(‖λ‖∞, ρ_max ‖v − v(t_{k−1})‖∞)
// (the interface form's scale with the instant's motion for the free one, which this form never
// solves), or where F reaches the noise of the solves (kNoiseMargin below): the forces are read off
// an equilibrium solved to a relative residual, so they are as exact as the solves and no more.
//
// Globalised as the interface form's Newton (newton_instant.hpp): backtracking on ‖F‖₂ along the
// step in u, the forces read off the equilibrium at each trial point (no solve).
//
// Cost: one solve per iteration, each warm (about two per instant in contact on the presses); the
// backend's preconditioner of K_ff reused for every held set (cg-gamg), so no set-up after the
// first. Each instant starts from the linear extrapolation of the two before (u and λ, hence the
// predicted active set).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "stcontact/contact/contact_state.hpp"
#include "stcontact/incremental/newton_instant.hpp"
#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/problem/problem.hpp"

namespace stc {

/// The free dof each row of B reads and its coefficient b_r (explicit zeros skipped): dof −1 for a
/// row that reads none (a held row), −2 for a row that reads several.
struct ContactRowDofs {
  std::vector<int> dof;
  Eigen::VectorXd coefficient;
};
ContactRowDofs contactRowDofs(const Eigen::SparseMatrix<double>& B);

/// Why `problem` cannot be solved in the whole-body form on `stiffness` (empty when it can): a pair
/// of bodies, held rows, a contact row reading other than one free dof (or two rows one dof), a
/// backend that does not hold dofs.
std::string wholeBodyRefusal(const Problem& problem, const SpdSolver& stiffness);

class WholeBodyLaw {
 public:
  /// Throws InputError with wholeBodyRefusal's reason when there is one.
  WholeBodyLaw(const Problem& problem, const SpdSolver& stiffness);

  /// Instant k from instant k − 1's forces and interface displacements (zeros before k = 0) and
  /// the displacement this object holds (instant k − 1's; zero at first), which becomes instant k's
  /// when the outcome converges. `iterations` counts solves.
  InstantOutcome solve(int k, const Eigen::VectorXd& lambda_previous, const Eigen::VectorXd& v_previous,
                       double tolerance, int max_iterations);
  int solves() const { return solves_; }

  /// The instant's stop above the solves' noise: ‖F‖∞ ≤ max(tolerance S_k, kNoiseMargin ν), ν the
  /// last solve's equilibrium residual ‖(K_ff u − f)_F‖₂ on the rows it solved (F: neither held nor
  /// replaced), which bounds the error of the forces read off the held rows to about ν.
  static constexpr double kNoiseMargin = 4.0;

 private:
  struct Evaluation {
    Eigen::VectorXd F;
    std::vector<ContactState> piece;  ///< per node
    Eigen::MatrixXd unit;             ///< (d − 1) × n_C: a slipping node's ξ̂
    Eigen::VectorXd q;                ///< per node: a slipping node's μ λ̂_n / |ξ|
  };

  Evaluation evaluate(const Eigen::VectorXd& lambda, const Eigen::VectorXd& v, const Eigen::VectorXd& v_previous) const;
  /// One solve with `e`'s active set at instant k (u_ updated), and the forces λ.
  Eigen::VectorXd solveActiveSet(const Evaluation& e, const Eigen::VectorXd& f, const Eigen::VectorXd& v_previous);
  /// Node i's slipping rows of the Newton system (see above), appended to `rows`, their right-hand
  /// side written into b.
  void addSlipRows(int i, const Evaluation& e, const Eigen::VectorXd& f, const Eigen::VectorXd& v_previous,
                   std::vector<Eigen::Triplet<double>>& rows, std::vector<int>& dofs, Eigen::VectorXd& b) const;

  void predict(int k, const Eigen::VectorXd& lambda_previous, InstantOutcome& out);
  /// Whether the instant stops at out's iterate (its residual set), and the step from u_from (where
  /// ‖F‖₂ was phi0) to u_ shortened until ‖F‖₂ decreases (the .cpp): u_, out's λ and v, and e at the
  /// point taken.
  bool stops(InstantOutcome& out, const Evaluation& e, const Eigen::VectorXd& v_previous, double tolerance) const;
  void backtrack(const Eigen::VectorXd& u_from, double phi0, const Eigen::VectorXd& f,
                 const Eigen::VectorXd& v_previous, InstantOutcome& out, Evaluation& e);

  const Problem& problem_;
  const ContactInterface& contact_;
  const SpdSolver& stiffness_;
  int d_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> K_;  ///< K_ff, both triangles
  std::vector<int> dof_;        ///< per row: the free dof it reads
  Eigen::VectorXd coefficient_;  ///< per row: b_r
  Eigen::VectorXd rho_n_, rho_t_;  ///< per node
  double rho_max_ = 0.0;
  Eigen::VectorXd u_;
  struct {
    Eigen::VectorXd u, lambda;
  } before_;  ///< instant k − 2's, for the prediction
  int solves_ = 0;
  double noise_ = 0.0;  ///< ν of the last solve
};

}  // namespace stc
