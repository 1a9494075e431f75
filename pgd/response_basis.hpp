#pragma once
// The responses of the global-stage operator A = K_ff + Bᵀ k B that the separated global stage
// reuses (docs/method.md §5, "Separated global stage"). The global stage's right-hand sides are
//   r_k = F g_k + Bᵀ w_k,   w_k = λ̂_k + k v̂_k   (loads in separated form, Problem::loads),
// so its solutions are u_k = U_F g_k + A⁻¹ Bᵀ w_k with the load responses U_F = A⁻¹ F (q solves,
// once). For the interface part the basis keeps directions Z = [z_1 … z_p] (d n_C × p, orthonormal
// in the k⁻¹ product: Zᵀ k⁻¹ Z = I), their responses X = A⁻¹ Bᵀ Z (n_free × p: the spatial modes
// of the separated displacement u_k ≈ U_F g_k + X c_k) and their traces T = B X (d n_C × p), and the
// Cholesky factor of the energy Gram matrix of Φ = [U_F X] (pgd/energy_factor.hpp), from traces:
//   U_Fᵀ A U_F = U_Fᵀ F,   U_Fᵀ A X = U_Fᵀ Bᵀ Z = V_Fᵀ Z,   Xᵀ A X = Xᵀ Bᵀ Z = Tᵀ Z.
// Nothing here is n_free × m: memory O((q + p) n_free + (q + p + m) n_C). The interface's columns
// are appended to storage with spare capacity (pgd/column_store.hpp: the accessors are views), the
// responses X kept as the blocks they were solved in (pgd/column_blocks.hpp: no copy as they grow).
// When the factor ordered the interface's dofs last (SpdSolver::condenses B), the operator
// D = B A⁻¹ Bᵀ comes from its trailing block with no solve, and a new direction's trace is T = D Z:
// the iteration then makes no sparse solve, and the responses X are solved only when asked for
// (responses(): the spatial modes of a verification), the displacements of other rows through the
// rank of the history instead (displacementOn).
// Where it does not, each direction's response is solved for its trace and kept while X fits in the
// bytes the basis was given; beyond, X is released and the traces alone are kept, as with the
// trailing block: the iteration is the same, and what needs X later (responsesOf, displacementOn,
// the spatial modes) solves it again through the rank of what it asks for (at 10⁶ dofs X would
// outgrow the machine before the iteration ends: docs/linear_solvers.md, "A million degrees of freedom").
#include <Eigen/Core>
#include <functional>
#include <limits>
#include <vector>

#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/pgd/column_blocks.hpp"
#include "stcontact/pgd/column_store.hpp"
#include "stcontact/pgd/energy_factor.hpp"
#include "stcontact/problem/problem.hpp"

namespace stc::pgd {

class ResponseBasis {
 public:
  using View = ColumnStore::View;
  /// `factor` factorises A = K_ff + Bᵀ k B, k = problem.contact.search_direction; `response_bytes`:
  /// the most the responses X may hold where the factor does not condense the interface (header).
  ResponseBasis(const Problem& problem, const SpdSolver& factor,
                double response_bytes = std::numeric_limits<double>::infinity());

  int size() const { return static_cast<int>(Z_.cols()); }       ///< p
  int maxSize() const { return static_cast<int>(Z_.rows()); }    ///< d n_C: Z then spans every w
  View directions() const { return Z_.view(); }                  ///< Z, d n_C × p
  View scaledDirections() const { return Zs_.view(); }           ///< k^{-1/2} Z: orthonormal columns
  /// X = A⁻¹ Bᵀ Z, n_free × p, in blocks (solved now for the directions whose responses were not).
  /// Throws std::logic_error once they were released (holdsResponses(): use responsesOf).
  const ColumnBlocks& responses() const;
  /// False once the responses outgrew the bytes the basis was given and were released (header).
  bool holdsResponses() const { return !released_; }
  View traces() const { return T_.view(); }                      ///< T = B X, d n_C × p
  const Eigen::MatrixXd& loadResponses() const { return UF_; }   ///< U_F = A⁻¹ F, n_free × q
  const Eigen::MatrixXd& loadTraces() const { return VF_; }      ///< V_F = B U_F, d n_C × q
  const Eigen::MatrixXd& loadHistories() const { return G_; }    ///< G, q × m
  const Eigen::MatrixXd& freeResponse() const { return v0_; }    ///< V_F G: v of w = 0, d n_C × m
  /// The Cholesky factor of ΦᵀAΦ, Φ = [U_F X] (q + p columns).
  const EnergyFactor& energyFactor() const { return energy_; }
  /// √k and 1/√k per interface row: the k⁻¹ product is the Euclidean one of k^{-1/2} w.
  const Eigen::VectorXd& sqrtK() const { return sqrt_k_; }
  const Eigen::VectorXd& invSqrtK() const { return inv_sqrt_k_; }

  /// Appends the columns of `candidates` (d n_C × b), k⁻¹-orthogonalised against the directions
  /// (block classical Gram–Schmidt, a second pass for the columns the first one shortened by more
  /// than 1 − 1/√2) and each other (in order, twice), dropping those left with less
  /// than `drop` of their norm, and solves for their responses (one multi-right-hand-side solve).
  /// Returns the number appended.
  int append(const Eigen::MatrixXd& candidates, double drop = 1e-8);
  /// append's directions without their responses, which stay pending until solvePending(): the
  /// enrichment passes of one separated stage append a few directions each and solve them in one
  /// block, since a supernodal (3D) solve costs less per column the more columns it takes at once
  /// (src/linalg/backends/cholmod_factor.cpp). Until then responses(), traces() and energyFactor() lack them.
  int appendDirections(const Eigen::MatrixXd& candidates, double drop = 1e-8);
  /// Completes the directions to span every interface row (size() becomes maxSize()): the pending
  /// ones solved, then an orthonormal complement of Zs appended (linalg::orthonormalComplement),
  /// with T = D Z and the energy factor extended; no sparse solve. Throws std::logic_error unless
  /// condensesInterface().
  void completeToEveryRow();
  /// Told (solved, pending) between the parts of a long solvePending: where it is.
  using SolveProgress = std::function<void(Eigen::Index solved, Eigen::Index pending)>;
  /// Columns per part of solvePending when a progress is told, on an iterative backend (about a
  /// minute at 10⁶ dofs on two ranks with CG + GAMG, 3 to 5 s per direction).
  static constexpr Eigen::Index kProgressColumns = 16;
  /// Solves the pending directions' responses in one multi-right-hand-side solve, stores them and
  /// their traces, and extends the energy factor. `loosening` (empty, or one ≥ 1 per pending
  /// direction): how many times the factor's relative residual each may be solved to, on an
  /// iterative backend (SpdSolver::solveLoosened; a direct one solves exactly as without it).
  /// With `progress`, on an iterative backend (each column its own solve: the same numbers), in parts
  /// of kProgressColumns, `progress` told after each; a direct factor solves them at once, untold.
  void solvePending(const Eigen::VectorXd& loosening = Eigen::VectorXd(), const SolveProgress& progress = {});
  /// The same basis on another time grid of the same problem (`grid`: stc::onInstants of it, or the
  /// problem itself again): the load histories G and the free response V_F G are taken on its
  /// instants, everything else (directions, responses, energy factor) is spatial and kept. Throws
  /// std::invalid_argument when `grid` has other load vectors, free dofs or interface rows.
  void retime(const Problem& grid);
  /// X_p M (n_free × k) for the first p = M.rows() directions: with X when their responses are
  /// known, else A⁻¹ Bᵀ (Z_p M), k solves (half-solves when the factor condenses the interface).
  Eigen::MatrixXd responsesOf(const Eigen::MatrixXd& M) const;
  /// Right-hand sides solved so far (loads included).
  long sparseSolves() const { return sparse_solves_; }
  /// Whether the traces come from D = B A⁻¹ Bᵀ of the factor's trailing block (no solve per direction).
  bool condensesInterface() const { return condensed_.size() > 0; }
  /// D = B A⁻¹ Bᵀ (d n_C × d n_C) when condensesInterface(), else empty.
  const Eigen::MatrixXd& condensedInterface() const { return condensed_; }
  /// B_rows (U_F G + X c), the displacements on other rows (e.g. of contact nodes left out) of the
  /// history with coordinates c (p' × m, p' ≤ p): with X when every response is known, else
  /// B_rows U_F G + B_rows A⁻¹ Bᵀ (Z c) with rank(Z c) solves (linalg/low_rank_solve.hpp).
  Eigen::MatrixXd displacementOn(const Eigen::SparseMatrix<double>& B_rows, const Eigen::MatrixXd& c) const;
  /// Keeps, beside T = B X, the traces B_rows X on other rows (e.g. the contact nodes left out of a
  /// zone: d n_F × p, n_F × 3 × 8 bytes per direction), taken from each response as it is solved, so
  /// that displacementOnKeptRows needs no solve, X released or not. No effect where the factor
  /// condenses the interface (no response is solved per direction there: displacementOn solves
  /// through the rank). Throws std::logic_error once a direction was appended, std::invalid_argument
  /// for rows of another width than n_free.
  void keepTracesOn(const Eigen::SparseMatrix<double>& B_rows);
  /// Whether keepTracesOn's rows have the traces of the first p directions.
  bool keepsTracesFor(Eigen::Index p) const { return kept_rows_.rows() > 0 && kept_traces_.cols() >= p; }
  /// B_rows (U_F G + X c) on keepTracesOn's rows, exact, from the traces kept: no solve. Throws
  /// std::logic_error unless keepsTracesFor(c.rows()).
  Eigen::MatrixXd displacementOnKeptRows(const Eigen::MatrixXd& c) const;
  /// The same, of the history truncated in energy: with Θ = [G; c] and its whitened coordinates
  /// R Θ = U Σ Vᵀ (energy_factor.hpp: u = Φ̂ R Θ, Φ̂ A-orthonormal), the fewest ρ modes whose
  /// dropped energy Σ_{i>ρ} σ_i² = Σ_k ‖u_k − u_ρ,k‖²_A is at most `energy_budget`,
  ///   B_rows u_ρ = B_rows Φ C Σ_ρ V_ρᵀ,   Φ C = Φ̂ U_ρ (EnergyFactor::combination),
  /// with at most ρ solves (none when every response is known). Since K_ff ≤ A = K_ff + Bᵀ k B, the
  /// dropped energy bounds Σ_k δu_kᵀ K δu_k too (δu has no prescribed part). `energy_budget` ≤ 0,
  /// or a truncation that keeps every mode: displacementOn(B_rows, c).
  Eigen::MatrixXd displacementOn(const Eigen::SparseMatrix<double>& B_rows, const Eigen::MatrixXd& c,
                                 double energy_budget) const;

 private:
  /// k^{-1/2}-scaled candidates made orthonormal to Zs and each other; dependent ones dropped.
  Eigen::MatrixXd orthonormalised(const Eigen::MatrixXd& candidates, double drop) const;
  void extendEnergyFactor(Eigen::Index added);  ///< the energy factor's columns for the new directions
  /// Keeps the new directions' responses X (moved into X_, no copy) while X_ with them stays within
  /// response_bytes_; else releases X_ for good (header).
  void keepOrRelease(Eigen::MatrixXd&& X);
  /// A⁻¹ Bᵀ M (n_free × k), k solves counted: half-solves from the factor's trailing block when it
  /// condenses the interface (SpdSolver::solveFromTrailing: the forward substitution of Bᵀ M, zero
  /// above that block, is the block's alone), else solveColumns.
  Eigen::MatrixXd solveInterfaceLoads(const Eigen::MatrixXd& M) const;
  /// A⁻¹ rhs, its columns solved in parts of 4 spread over threadCount() threads (the parts do not
  /// depend on the thread count, so neither does the result).
  Eigen::MatrixXd solveColumns(const Eigen::MatrixXd& rhs) const;
  /// A⁻¹ rhs, each column loosened as asked on an iterative backend (solvePending), in parts of
  /// kProgressColumns told to `progress` when one is given.
  Eigen::MatrixXd solveNewResponses(const Eigen::MatrixXd& rhs, const Eigen::VectorXd& loosening,
                                    const SolveProgress& progress) const;
  /// B_rows A⁻¹ Bᵀ (Z_p M) for the first p = M.rows() directions: with X when their responses are
  /// known, else through the rank of Z_p M (linalg/low_rank_solve.hpp).
  Eigen::MatrixXd liftedInterface(const Eigen::SparseMatrix<double>& B_rows, const Eigen::MatrixXd& M) const;
  /// The same for modes M (p × ρ) of singular values σ (> 0): where an iterative backend solves, the
  /// modes weighted by σ and the result unweighted, the same product, so that solveThroughRank sees
  /// the small modes as small and loosens their solves (linalg/low_rank_solve.hpp).
  Eigen::MatrixXd liftedModes(const Eigen::SparseMatrix<double>& B_rows, const Eigen::MatrixXd& M,
                              const Eigen::VectorXd& sigma) const;

  const Problem& problem_;
  const SpdSolver& factor_;
  Eigen::VectorXd sqrt_k_, inv_sqrt_k_;
  Eigen::MatrixXd condensed_;  ///< D = B A⁻¹ Bᵀ from the factor's trailing block, or empty
  ColumnStore Z_, Zs_, T_;
  mutable ColumnBlocks X_;     ///< behind Z_ when D gives the traces: solved by responses()
  double response_bytes_;      ///< the most X_ may hold where each direction is solved
  bool released_ = false;      ///< X_ outgrew response_bytes_ and was released: traces alone
  Eigen::SparseMatrix<double> kept_rows_;  ///< keepTracesOn's rows, or none
  ColumnBlocks kept_traces_;   ///< kept_rows_ X
  Eigen::MatrixXd UF_, VF_, G_, v0_;
  EnergyFactor energy_;
  mutable std::vector<SpdSolver::Workspace> workspaces_;
  mutable long sparse_solves_ = 0;
  Eigen::Index pending_ = 0;
};

}  // namespace stc::pgd
