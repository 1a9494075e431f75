#pragma once
// LATIN's global stage in separated form, with its error controlled (docs/method.md §5,
// "Separated global stage"). With the response basis (pgd/response_basis.hpp) and w = λ̂ + k v̂:
//   c = Zᵀ k⁻¹ w,   r = w − Z c              (projection on the known directions; r its error)
//   v = V_F G + T c,   λ = Z c − k v          (the exact global stage of the projected w)
// so s = (v, λ) is exactly in equilibrium (K_ff u = F g + Bᵀλ with u = U_F g + X c) and departs from
// the exact global stage of ŝ by δv = −D r, δλ = −(I − k D) r (D = B A⁻¹ Bᵀ). As 0 ≤ k^½ D k^½ ≤ I,
//   ‖r‖_{k⁻¹} / √2 ≤ ‖δs‖ ≤ ‖r‖_{k⁻¹}     (indicator norm, docs/method.md §2).
// Control: before s is formed, the directions are enriched with the leading singular directions
// of r (randomized range finder, Halko–Martinsson–Tropp 2011 alg. 4.4) until ‖r‖_{k⁻¹} ≤ γ ‖s − ŝ‖
// of the previous iteration (observeGap). A perturbation ε_n ≤ γ ‖s_{n−1} − ŝ_{n−1}‖ keeps a
// contraction of rate ρ a contraction of rate about ρ + γ (the gap is of the size of the distance to
// the fixed point), and vanishes with the gap: the iteration converges to the fixed point of the
// exact global stage. Each solve costs three products with p columns on d n_C × m interface fields,
// plus one sparse solve per new direction.
//
// Every row. When the factor gives D = B A⁻¹ Bᵀ from its trailing block (ResponseBasis::
// condensesInterface) and the directions reach ControlledStageOptions::full_share of the d n_C rows,
// they are completed to span them all (ResponseBasis::completeToEveryRow, no sparse solve). Then
// r = 0, and with T Zsᵀ k^{-1/2} = D k^{1/2} Zs Zsᵀ k^{-1/2} = D the stage is exact,
//   v = V_F G + D w,   λ = w − k v,
// one product with d n_C columns where a solve took three with p, and no enrichment; c = Zsᵀ w̃ is
// formed only when asked for. On the zones of 801 arc nodes and of the graded half-ball the
// enrichment ends at 391 of 462 and 606 of 606 rows (docs/floor.md, "Every row").
//
// Inexact directions. On an iterative backend a direction's response is solved to the relative
// residual ρ_j = min(ℓ_j ρ, 1e-4) (ρ: solver.linear_rtol's; 1e-4: LinearSolverOptions::kLoosestRtol),
// and its error e_j = X̃_j − X_j enters the iterates through its coordinates alone:
// δv = Σ_j (B e_j) c_j. A direction whose coordinates weigh ‖c_j‖ ≪ ‖w̃‖ may take a looser solve
// for the same δv, as the inexact matrix–vector products of a Krylov method may loosen as its
// residual falls (Simoncini & Szyld, SIAM J. Sci. Comput. 25, 2003; Bouras & Frayssé, SIAM J. Matrix
// Anal. Appl. 26, 2005). Its coordinates at the fixed point differ from today's by at most the
// distance to the fixed point, of the size of the last gap g = ‖s − ŝ‖:
//   ℓ_j = min(L, max(1, ‖w̃‖ / (‖c_j‖ + g))),   L = ControlledStageOptions::loosening_cap,
// so each direction's share of δv stays at about ρ ‖w̃‖, as with ℓ = 1 for the leading ones; ℓ = 1
// until a gap is known. ‖c_j‖ is the row's norm over the instants. A direct backend solves exactly.
// Measured in docs/linear_solvers.md, "Inexact directions".
#include "stcontact/latin/linear_stage.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/options/separated_stage_options.hpp"
#include "stcontact/pgd/response_basis.hpp"
#include "stcontact/solver/noted_phase.hpp"

namespace stc::pgd {

class ControlledGlobalStage : public latin::LinearStage {
 public:
  /// Factorises A = K_ff + Bᵀ k B (k = problem.contact.search_direction), the interface's dofs
  /// ordered last wherever SpdSolver's bounds on the dense trailing block allow (then no solve per
  /// direction, response_basis.hpp, and the stage spans every row from its full_share on), and
  /// computes the load responses. At any size, not from a work as the incremental solver's factor:
  /// that one saves the |J| solves of one Delassus operator, this one a solve for every direction
  /// and, once it spans every row, the enrichment (faster on every example scene but one, measured
  /// in docs/threads.md, "The Delassus operator from the factorisation").
  ControlledGlobalStage(const Problem& problem, ControlledStageOptions options);
  /// The same operator taken from `operators` (prepared there once for the run).
  ControlledGlobalStage(const Problem& problem, ControlledStageOptions options, PreparedOperators& operators);

  void solve(const InterfaceHistory& hat, InterfaceHistory& s) override;
  void observeGap(double gap) override { target_ = options_.gap_share * gap; }
  long sparseSolves() const override { return basis_.sparseSolves(); }
  int rank() const override { return basis_.size(); }
  bool changesItsMap() const override { return true; }
  const SpdSolver& factor() const override { return *operator_->factor; }

  /// Starts the directions from `directions` (d n_C × p, e.g. a neighbouring problem's: a warm
  /// start), k⁻¹-orthonormalised in order, dependent ones dropped. Returns the number kept.
  int seed(const Eigen::MatrixXd& directions);

  /// The stage on another time grid of the same problem (ResponseBasis::retime): the factor and the
  /// directions are kept, the coordinates of the last solve and the observed gap are dropped (the
  /// next solve's bound is a share of its right-hand side, as for a first solve). What nested
  /// iteration in time uses to solve on a sub-grid and then on the whole grid with one basis.
  void retime(const Problem& grid);
  const ResponseBasis& basis() const { return basis_; }
  /// Tells `note` where a long enrichment is, at most once per `interval` seconds of its solves:
  /// "global stage: 48 of 310 new directions solved (1 204 in all), 63.0 s" (src/solver/noted_phase.hpp;
  /// at 10⁶ dofs a first relaxation's directions take more than ten minutes on two ranks). None: silent.
  void notePhases(PhaseNote note, double interval = NotedPhase::kDuringInterval) {
    note_ = std::move(note);
    note_interval_ = interval;
  }
  /// The basis keeps its responses' traces on `B_rows` too (ResponseBasis::keepTracesOn): before
  /// the first direction, seed() included.
  void keepTracesOn(const Eigen::SparseMatrix<double>& B_rows) { basis_.keepTracesOn(B_rows); }
  const Eigen::SparseMatrix<double>& matrix() const { return operator_->matrix; }
  /// c of the last solve (p × m): the displacement history is u_k = U_F g_k + X c_k.
  const Eigen::MatrixXd& coordinates() const;
  /// Whether the directions span every interface row (the exact stage of the header's "Every row").
  bool spansEveryRow() const { return every_row_; }
  /// ‖r‖_{k⁻¹} of the last solve, and the bound it was held to.
  double projectionError() const override { return error_; }
  /// The coordinates c (p × m) that a solve from `hat` would have, the directions enriched as that
  /// solve would enrich them (the same bound): the projection of the next right-hand side, without
  /// forming s (two products with the directions where a solve has three; fas/apriori/apriori_basis.hpp
  /// builds the coarse space from it). The last solve's coordinates() are kept; the directions
  /// added stay.
  Eigen::MatrixXd anticipate(const InterfaceHistory& hat);
  /// The anticipated history's energy coordinates R [G; c] (whitenedHistory(basis(),
  /// anticipate(hat))): what the coarse space is built from. Once the
  /// directions span every row, c = Z̃ᵀ w̃ and R [G; c] = R_G G + (R_Z Z̃ᵀ) w̃ with R_Z Z̃ᵀ formed once,
  /// one product per call instead of two.
  ///
  /// With `step_samples` > 0, also `step` = R [0; (c − c_last) Ω]: the energy coordinates of
  /// `step_samples` Gaussian combinations (Ω, m × step_samples, a fixed seed, scaled by
  /// 1/√step_samples) of ũ − ũ_last, the change the next global stage makes to the last one's
  /// displacement history (c_last padded with zeros for directions added since: ũ_last = X c_last).
  /// Empty before a solve, after retime, and in the call that completes the directions. Once they
  /// span every row it is (R_Z Z̃ᵀ)(w̃ − w̃_last) Ω, in the same product as the history.
  struct Anticipated {
    Eigen::MatrixXd whitened;
    Eigen::MatrixXd step;
  };
  Anticipated anticipateWhitened(const InterfaceHistory& hat, int step_samples = 0);
  /// Ω of anticipateWhitened's step, m × samples.
  static Eigen::MatrixXd stepSketch(Eigen::Index instants, int samples);

 private:
  /// The exact stage when the directions span every row (solve's "Every row" case).
  void solveEveryRow(const InterfaceHistory& hat, InterfaceHistory& s);
  /// w̃ = k^{-1/2} (λ̂ + k v̂), the scaled right-hand sides of a solve from `hat`.
  Eigen::MatrixXd scaledRightHandSides(const InterfaceHistory& hat) const;
  /// The same written into `out` (d n_C × m): a buffer kept from call to call.
  void writeScaledRightHandSides(const InterfaceHistory& hat, Eigen::Ref<Eigen::MatrixXd> out) const;
  /// c = Z̃ᵀ w̃ and r̃ = w̃ − Z̃ c, enriched until ‖r̃‖ is at most the current bound. Returns ‖r̃‖.
  double project(const Eigen::MatrixXd& w_scaled, Eigen::MatrixXd& c, Eigen::MatrixXd& r_scaled);
  /// Adds directions from the scaled residual r̃ = k^{-1/2} r while its norm `error` exceeds
  /// `target`, solved each to its loosening (header, "Inexact directions") from ‖w̃‖ = `w_norm`;
  /// updates c and r̃, returns the final ‖r̃‖.
  double enrich(Eigen::MatrixXd& c, Eigen::MatrixXd& r_scaled, double error, double target, double w_norm);
  /// ℓ_j of each new direction from its coordinates c_new (header, "Inexact directions").
  Eigen::VectorXd loosenings(const Eigen::MatrixXd& c_new, double w_norm) const;
  /// basis_.solvePending, told to notePhases' note as "<solved> of <pending> <which> directions solved".
  void solvePendingNoted(const Eigen::VectorXd& loosening, const std::string& which);
  /// Completes the directions to every row once they reach the share of the options (header).
  void completeWhenDue();

  const Problem& problem_;
  ControlledStageOptions options_;
  PhaseNote note_;                ///< notePhases'
  double note_interval_ = NotedPhase::kDuringInterval;
  std::shared_ptr<const SearchOperator> operator_;
  ResponseBasis basis_;
  mutable Eigen::MatrixXd c_;
  Eigen::MatrixXd w_last_;        ///< w̃ of the last exact solve (every row)
  mutable bool c_stale_ = false;  ///< c_ not yet formed from w_last_ (coordinates())
  Eigen::MatrixXd whitened_rows_;   ///< R_Z Z̃ᵀ once the directions span every row (anticipateWhitened)
  /// Interface-sized work arrays of the exact stage and of anticipateWhitened, kept from call to
  /// call: at 10⁴ instants each is tens of MB, which the allocator maps afresh every time (the page
  /// clearing under these two calls was 12 % of a fretting solve at divisions 16 and 10 001
  /// instants, docs/scale.md).
  struct Buffers {
    Eigen::MatrixXd solved;       ///< w = λ̂ + k v̂ of solve
    Eigen::MatrixXd anticipated;  ///< [w̃, (w̃ − w̃_last) Ω] of anticipateWhitened
    Eigen::MatrixXd product;      ///< R_Z Z̃ᵀ [w̃, (w̃ − w̃_last) Ω]
  };
  Buffers buffers_;
  bool every_row_ = false;
  double target_ = -1.0;  ///< < 0: no gap observed yet
  double error_ = 0.0;
  unsigned passes_ = 0;   ///< enrichment passes so far (seeds the range finder: deterministic)
};

}  // namespace stc::pgd
