#pragma once
// The incremental solver on the contact nodes the prescribed motion can reach (issue "the strongest
// yardstick"). When the loading is a prescribed translation w(t) alone, the nodes that w, carried
// rigidly, never brings to the obstacle (g0_i + min_k n_i · w(t_k) > 0, src/problem/prescribed_reach.hpp)
// are left out of the dense law: W is formed on the zone Z only,
//   W_ZZ = B_Z K⁻¹ B_Zᵀ,
// from the trailing block of a factor of K_ff with the zone's dofs ordered last (no solve,
// SpdSolver::condensed; where that pays, src/linalg/backends/cholmod_factor.hpp) or from d |Z| sparse solves, and the other
// nodes' displacements follow, with λ_F = 0, as
//   v_F(t_k) = v_0,F(t_k) + W_FZ λ_Z(t_k),   W_FZ = B_F K⁻¹ B_Zᵀ,
// from the same solves, or from rank(λ_Z) solves after the march (ZoneCondensation::lift). That is the whole problem's solution exactly when no node of F penetrates
// (g0_i + v_n,i ≥ 0 at every instant): an open node with λ = 0 satisfies its law, and the zone's
// equations are the whole problem's rows of Z (same W_ZZ, v_0,Z). The check is made after the
// solve; a node that fails it sends the solve to the whole interface (incremental_solver.cpp).
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "stcontact/incremental/condensed_interface.hpp"
#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc {

/// The nodes within reach of the prescribed translation (margin 0), increasing, when the loading is
/// one and they are some but not all of the contact nodes; none otherwise (solve on every node).
std::optional<std::vector<int>> reachZone(const Problem& problem);

/// The condensed interface of the zone, and what lifts its solution to every node. W_ZZ comes from
/// the trailing block of a factor that ordered the zone's dofs last (SpdSolver::condenses), else
/// from d |Z| solves, which give W_FZ as well. Without W_FZ the lift solves for the far nodes'
/// displacements, as many right-hand sides as λ_Z has rank.
struct ZoneCondensation {
  std::vector<int> zone, far;     ///< the zone's nodes Z and the others F, increasing
  CondensedInterface on_zone;     ///< W_ZZ, v_0,Z; sparse_solves: load terms (+ d |Z| by solves)
  Eigen::MatrixXd far_delassus;   ///< W_FZ (d |F| × d |Z|) when W_ZZ came from solves, else empty
  Eigen::MatrixXd far_free;       ///< v_0,F (d |F| × m)
  Eigen::SparseMatrix<double> B_zone, B_far;  ///< B's rows of the zone and of the nodes left out

  static ZoneCondensation build(const Problem& problem, const SpdSolver& stiffness_free, std::vector<int> zone);

  /// The whole interface's history from the zone's on its first `solved` instants (λ_F = 0,
  /// v_F = v_0,F + W_FZ λ_Z); the later instants stay zero, as a stopped march leaves them. Adds the
  /// sparse solves it makes (none when W_FZ is known) to `sparse_solves`.
  InterfaceHistory lift(const ContactInterface& contact, const SpdSolver& stiffness_free,
                        const InterfaceHistory& on_zone, int solved, long& sparse_solves) const;
};

/// Nodes of `far` whose gap g0_i + v_n,i falls below −tolerance · max(‖v(:, k)‖∞, max_j |g0_j|)
/// at some instant k, or is not a number: the nodes the zone's solution pushes into the obstacle
/// (or cannot tell about), increasing.
std::vector<int> penetratingNodes(const ContactInterface& contact, const InterfaceHistory& h,
                                  const std::vector<int>& far, double tolerance);

}  // namespace stc
