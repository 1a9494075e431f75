#pragma once
// The contact output tables of docs/interface.md: reactions.csv (one row per instant) and contact.csv
// (one row per contact node and instant), computed from a solution's interface histories.
#include <Eigen/Core>
#include <cstdint>
#include <ostream>
#include <vector>

#include "stcontact/problem/problem.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc {

/// The interface histories per instant, contact node and component beside λ, row-major (instant,
/// node, component) as solution.h5 stores them: gap = g0 + v_n (m × n_C), slip (m × n_C × (d − 1)),
/// state (m × n_C: 0 open, 1 stick, 2 slip). The slip is the tangential increment
/// v_t(t_k) − v_t(t_{k−1}) (v_t(t_{−1}) = 0) where the node is in contact (stick or slip) and 0
/// where it is open: an open node has no surface to slip on (its motion is the displacement
/// field's). Pressure and shear are λ over the tributary length or area ℓ_i.
struct InterfaceTable {
  int steps = 0, nodes = 0, tangential = 0;  ///< m, n_C, d − 1
  std::vector<double> gap, slip;
  std::vector<std::int8_t> state;
};
InterfaceTable interfaceTable(const Problem& problem, const SolveResult& result);

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
ReactionTable reactionTable(const Problem& problem, const SolveResult& result, const InterfaceTable& table);
ReactionTable reactionTable(const Problem& problem, const SolveResult& result);

/// step,t,normal_force,tangential_force,contact_xmin,contact_xmax,n_contact,n_slip,force_x,force_y —
/// totals of the contact forces on the body; x-range, count of closed nodes and count of slipping
/// nodes; the resultant in the global frame. contact_xmin/xmax are empty when no node is closed. A 3D
/// scene adds tangential_force_2 after tangential_force and force_z at the end.
void writeReactionsCsv(std::ostream& out, const Problem& problem, const ReactionTable& table);
void writeReactionsCsv(std::ostream& out, const Problem& problem, const SolveResult& result);

/// step,t,node,x,y,normal_force,tangential_force,pressure,shear,gap,slip,state — node is the mesh
/// file's node tag (nodeTags: from 1 for a generated mesh), (x, y) its initial position, the rest InterfaceTable's (pressure/shear the nodal forces
/// over the tributary length, slip 0 where open), state open|stick|slip. A 3D scene writes
/// step,t,node,x,y,z,normal_force,tangential_force,tangential_force_2,pressure,shear,shear_2,gap,slip,slip_2,state
/// (the tangential components along τ_1 and τ_2 of ContactInterface, pressure and shears per
/// tributary area).
void writeContactCsv(std::ostream& out, const Problem& problem, const SolveResult& result, const InterfaceTable& table);
/// The size contact.csv would have, estimated (output.contact_csv = "auto" writes it below
/// kSmallContactCsvBytes).
double contactCsvBytes(const Problem& problem);
inline constexpr double kSmallContactCsvBytes = 8.0 * (1 << 20);

}  // namespace stc
