#pragma once
// The contact output tables of docs/interface.md: reactions.csv (one row per instant) and contact.csv
// (one row per contact node and instant), computed from a solution's interface histories.
#include <Eigen/Core>
#include <ostream>
#include <vector>

#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc {

/// The rows of reactions.csv as columns, one entry per instant: the totals of the contact forces on
/// the body, the x-range of the closed nodes (NaN when none is closed), their count and the count of
/// slipping ones. What writeReactionsCsv writes and the Python module returns (docs/python.md).
/// tangential_force is along τ_1 (2D: τ); tangential_force_2 along τ_2, 3D only (empty in 2D): sums
/// of each node's components in its own frame. force (d × m) is the resultant in the global frame,
/// Σ_i λ_n,i n_i + λ_t,i τ_i (+ λ_t2,i τ_2,i), what a curved obstacle's turning frames need.
struct ReactionTable {
  std::vector<double> t, normal_force, tangential_force, tangential_force_2, contact_xmin, contact_xmax;
  std::vector<int> n_contact, n_slip;
  Eigen::MatrixXd force;
};
ReactionTable reactionTable(const Problem& problem, const SolveResult& result);

/// step,t,normal_force,tangential_force,contact_xmin,contact_xmax,n_contact,n_slip,force_x,force_y —
/// totals of the contact forces on the body; x-range, count of closed nodes and count of slipping
/// nodes; the resultant in the global frame. contact_xmin/xmax are empty when no node is closed. A 3D
/// scene adds tangential_force_2 after tangential_force and force_z at the end.
void writeReactionsCsv(std::ostream& out, const Problem& problem, const SolveResult& result);

/// step,node,x,y,normal_force,tangential_force,pressure,shear,gap,slip,state — node is the mesh
/// node id, (x, y) its initial position, pressure/shear the nodal forces over the tributary length,
/// gap = g0 + v_n, slip = v_t(t_k) − v_t(t_{k−1}), state open|stick|slip. A 3D scene writes
/// step,node,x,y,z,normal_force,tangential_force,tangential_force_2,pressure,shear,shear_2,gap,slip,slip_2,state
/// (the tangential components along τ_1 and τ_2 of ContactInterface, pressure and shears per
/// tributary area).
void writeContactCsv(std::ostream& out, const Problem& problem, const SolveResult& result);

}  // namespace stc
