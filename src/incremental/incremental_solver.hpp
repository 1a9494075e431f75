#pragma once
// The incremental reference solver: the time-discrete problem of docs/method.md §1 solved instant by
// instant to machine precision. Every other solver's true error (docs/method.md §2) is measured against it.
//
// Method. K_ff is factorised once and the problem condensed on the interface
// (condensed_interface.hpp): v_k = v_0(:, k) + W λ_k, W = B K⁻¹ Bᵀ. Marching over k = 0 … m−1, the
// contact law at instant k is written node-wise as the Alart–Curnier equations (Alart & Curnier,
// CMAME 92, 1991, augmented-Lagrangian contact operator; implicit Coulomb with the slip increment
// of docs/method.md §1)
//   F_n = λ_n − max(0, λ_n − ρ_n g),                 g = g0 + v_n,
//   F_t = λ_t − clamp(λ_t − ρ_t s, −μ λ̂_n, μ λ̂_n),   s = v_t(t_k) − v_t(t_{k−1}), λ̂_n = max(0, λ_n − ρ_n g),
// whose roots are exactly the solutions of the law (F = 0 ⇔ Signorini and Coulomb at the node), and
// solved by a semismooth Newton method started from λ_{k−1}. F is piecewise linear in λ; a Newton
// step solves the linear piece selected by the current iterate, so it is a primal–dual active-set
// method: open nodes (λ_n − ρ_n g ≤ 0) get λ = 0 and are eliminated; closed nodes impose g = 0;
// sticking ones s = 0; slipping ones λ_t = σ μ λ_n (σ = sign of the trial λ_t − ρ_t s) and their λ_t is
// eliminated too. The dense Newton system therefore has one unknown per closed node plus one per
// sticking node (at most 2 × closed), is nonsymmetric when some node slips and is solved by LU with
// partial pivoting. Steps are computed as corrections, so that a repeated step on an unchanged active
// set is an iterative refinement that brings the residual to its round-off floor.
//
// Scaling: ρ_n,i = 1 / W_{2i,2i} and ρ_t,i = 1 / W_{2i+1,2i+1}, the stiffness node i alone offers in
// each direction; F is then a force at every node and the semismooth step is invariant to the units.
// Globalisation: backtracking on ‖F‖₂ (halving, Armijo constant 1e-4, at most 12 halvings); when no
// step length decreases ‖F‖ the full step is taken anyway (active-set methods often pass through a
// larger residual on their way to the right active set); the max_newton_iterations cap bounds cycling.
//
// Convergence at instant k: ‖F‖∞ ≤ tolerance · S_k with the force scale
//   S_k = max(‖λ_k‖∞, max_i ρ_i · ‖v_0(:, k)‖∞),
// i.e. relative to the largest contact force, or, before any force builds up, to the force that would
// push a node back by the instant's free motion. F_n = ρ_n g on closed nodes, so gaps and slips are
// then resolved to tolerance · S_k / ρ (about tolerance × the displacement scale). The floor of
// ‖F‖∞ / S_k set by round-off is below 1e-15 on the seed scene (measured: 4e-16), under the
// default 1e-13.
//
// Cost and size. The plane law (2D): 2n_C + (load terms) sparse solves to build W and v_0 (2|Z| +
// (load terms) on the zone within reach of a prescribed translation, reach_zone.hpp), then per
// Newton iteration O(n_C · n_A) to evaluate F and O(n_A³) for the LU (n_A: closed nodes); W is dense
// 2n_C × 2n_C, 32 n_C² bytes: 0.3 MB for the seed (n_C = 101), 3.2 GB for n_C = 10⁴. The cone law
// (every 3D scene, IncrementalOptions::cone_law in 2D) needs only the columns of W of the nodes that
// ever close (v = v_0 + W(:, A) λ_A, all rows to test the open nodes): computed lazily, d sparse
// solves per node the first time it closes (lazy_delassus.hpp), 8 d² n_C n_A,ever bytes. When the
// active set itself is large: do not form W at all and solve each Newton step as the sparse
// saddle-point system [K_ff  B_Aᵀ; B_A  0] (sparse LDLᵀ, or a Schur complement by CG preconditioned
// with diag(W)).
//
// IncrementalOptions::form = WholeBody solves the same law on the displacement of the whole body
// instead, one warm solve with the contact dofs held per active-set iteration and no column of W
// (whole_body_newton.hpp): for a rigid obstacle whose normal is an axis, on a backend that holds
// dofs (cg-gamg), where the Delassus columns are solves.
#include "stcontact/options/incremental_options.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_inputs.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc {

/// Solves every instant of `problem`. Returns the interface history (v, λ) and a summary: solver
/// "incremental", one IterationRecord per instant (iteration = k + 1, relaxations = 0, indicator =
/// the final ‖F‖∞ / S_k of the instant, sparse_solves cumulative, wall_s since the start) and
/// termination Converged, NumericalIssue (non-finite numbers or Newton failure; the message names the
/// instant) or StoppedByCallback (the callback is called after every instant). summary.indicator is
/// the largest final residual over the instants. The message always contains
/// "<N> Newton iterations" with N the total over the instants solved.
/// Of `inputs` it uses the callback alone (it marches from the unloaded state, and is exact).
/// Throws InputError if the options are invalid or K_ff is not positive definite.
SolveResult solveIncremental(const Problem& problem, const IncrementalOptions& options = {},
                             const SolveInputs& inputs = {});

}  // namespace stc
