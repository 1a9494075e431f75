#pragma once
// The contact law at one instant for any dimension d (2 or 3), as the model of solveInstantByNewton
// (newton_instant.hpp): the Alart–Curnier equations with the isotropic Coulomb cone (Alart &
// Curnier, CMAME 92, 1991; the cone's projection as in Christensen, Klarbring, Pang & Strömberg,
// IJNME 42, 1998), node by node, with s = v_t(t_k) − v_t(t_{k−1}) the slip increment:
//   λ̂_n = λ_n − ρ_n g,  g = g0 + v_n;
//   open  (λ̂_n ≤ 0):            F = λ;
//   closed, ξ = λ_t − ρ_t s:     F_n = ρ_n g,
//     stick (|ξ| ≤ μ λ̂_n):       F_t = ρ_t s,
//     slip:                      F_t = λ_t − μ λ̂_n ξ / |ξ|.
// F = 0 ⇔ Signorini and Coulomb at every node (λ̂_n ≤ 0 gives λ = 0 and g ≥ 0; otherwise g = 0,
// λ_n = λ̂_n > 0 and λ_t the projection of ξ on the disc of radius μ λ_n). In 2D this is the law of
// incremental_solver.hpp.
//
// Newton step: the generalised Jacobian ∂F = A + C W (A = ∂F/∂λ, C = ∂F/∂v, block diagonal):
//   open: A = I, C = 0;  closed normal row: C_nn = ρ_n;  stick: C_tt = ρ_t I;
//   slip: with q = μ λ̂_n / |ξ|, ξ̂ = ξ / |ξ|, P = I − ξ̂ ξ̂ᵀ:
//         A_tt = I − q P, A_tn = −μ ξ̂, C_tn = μ ρ_n ξ̂, C_tt = q ρ_t P.
// Open nodes get Δλ = −λ; the closed ones solve the dense d n_closed system
//   (A_CC + C_CC W_CC) Δλ_C = −F_C + C_CC W_CO λ_O  (LU with partial pivoting).
// While the closed set stays, only the rows of nodes that slip (or switch between stick and slip)
// change from one system to the next: one LU serves many Newton steps and instants, the changed
// rows through the Woodbury formula (src/linalg/row_updated_lu.hpp), and W_CC is gathered once.
//
// W is never formed: its columns come from LazyDelassus (lazy_delassus.hpp) for the nodes that
// carry a force or close. ρ_n = 1 / W_nn and ρ_t = (d − 1) / tr(W_tt) of the node, known once its
// columns are; an open node with λ = 0 needs none (λ̂_n = −ρ_n g > 0 ⇔ g < 0, whatever ρ_n > 0):
// its columns are computed the first time its gap is negative.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "stcontact/incremental/lazy_delassus.hpp"
#include "stcontact/incremental/newton_instant.hpp"
#include "stcontact/linalg/row_updated_lu.hpp"
#include "stcontact/options/incremental_options.hpp"
#include "stcontact/problem/problem.hpp"

namespace stc {

class ConeLaw {
 public:
  struct Evaluation {
    Eigen::VectorXd v;            // v = v_0 + W λ
    Eigen::VectorXd F;            // the residual above
    std::vector<bool> closed;     // per node
    Eigen::MatrixXd A, C;         // d × d n_C: the node blocks of ∂F/∂λ and ∂F/∂v
  };

  ConeLaw(const Problem& problem, LazyDelassus& delassus);

  /// Sets the instant: v_0(:, k) and the previous instant's interface displacements (zero for k = 0).
  void setInstant(const Eigen::VectorXd& v0, const Eigen::VectorXd& v_previous);

  /// Instant k by semismooth Newton (solveInstantByNewton) from the previous instant's forces and
  /// interface displacements, v0 = v_0(:, k) the free response there.
  InstantOutcome solveInstant(const Eigen::VectorXd& v0, const Eigen::VectorXd& lambda_previous,
                              const Eigen::VectorXd& v_previous, const IncrementalOptions& options);

  /// Computes the Delassus columns and the scaling ρ of `nodes` now, in blocks on every thread,
  /// rather than a few at a time as they first close (evaluate does that for the others).
  void prepare(const std::vector<int>& nodes) { learnScaling(nodes); }

  Evaluation evaluate(const Eigen::VectorXd& lambda);
  bool newtonStep(const Eigen::VectorXd& lambda, const Evaluation& e, Eigen::VectorXd& step);
  /// S_k = max(‖λ‖∞, max_i ρ_i ‖v_0(:, k)‖∞), the largest ρ_n or ρ_t known so far.
  double forceScale(const Eigen::VectorXd& lambda) const;
  /// The Newton systems solved so far: LU factorisations, updates of one (row_updated_lu.hpp).
  const linalg::RowUpdatedLu::Counts& newtonSystems() const { return system_.counts(); }
  /// The summary's remark on those systems.
  std::string systemsRemark() const;

 private:
  Eigen::VectorXd displacement(const Eigen::VectorXd& lambda) const;
  void learnScaling(const std::vector<int>& nodes);
  void nodeLaw(int i, const Eigen::VectorXd& lambda, Evaluation& e) const;
  /// Brings M_ to this step's Newton matrix, forming again only the block rows whose node's A or C
  /// changed (`rebuilt`: every row, after a new closed set), and returns those rows.
  template <int D>
  std::vector<Eigen::Index> newtonSystem(const std::vector<int>& closed, const Evaluation& e,
                                         const Eigen::VectorXd& open_response, bool rebuilt, Eigen::VectorXd& rhs);

  const ContactInterface& contact_;
  LazyDelassus& W_;
  int d_;
  Eigen::VectorXd rho_n_, rho_t_;  // per node, 0 until its columns exist
  double rho_max_ = 0.0;
  Eigen::VectorXd v0_, v_previous_;
  std::vector<int> closed_;  // the closed set of W_CC_
  Eigen::MatrixXd W_CC_;
  Eigen::MatrixXd M_;                  // the last Newton matrix, A_CC + C_CC W_CC on closed_
  Eigen::MatrixXd formed_A_, formed_C_;  // d × d |closed_|: the node blocks M_'s rows were formed with
  linalg::RowUpdatedLu system_;
};

}  // namespace stc
