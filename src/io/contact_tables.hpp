#pragma once
// The contact output tables of docs/interface.md: reactions.csv (one row per instant) and contact.csv
// (one row per contact node and instant), computed from a solution's interface histories.
#include <ostream>
#include <vector>

#include "src/problem/problem.hpp"
#include "src/solver/solve_result.hpp"

namespace stc {

/// The rows of reactions.csv as columns, one entry per instant: the totals of the contact forces on
/// the body, the x-range of the closed nodes (NaN when none is closed), their count and the count of
/// slipping ones. What writeReactionsCsv writes and the Python module returns (docs/python.md).
struct ReactionTable {
  std::vector<double> t, normal_force, tangential_force, contact_xmin, contact_xmax;
  std::vector<int> n_contact, n_slip;
};
ReactionTable reactionTable(const Problem& problem, const SolveResult& result);

/// step,t,normal_force,tangential_force,contact_xmin,contact_xmax,n_contact,n_slip — totals of the
/// contact forces on the body; x-range, count of closed nodes and count of slipping nodes.
/// contact_xmin/xmax are empty when no node is closed.
void writeReactionsCsv(std::ostream& out, const Problem& problem, const SolveResult& result);

/// step,node,x,y,normal_force,tangential_force,pressure,shear,gap,slip,state — node is the mesh
/// node id, (x, y) its initial position, pressure/shear the nodal forces over the tributary length,
/// gap = g0 + v_n, slip = v_t(t_k) − v_t(t_{k−1}), state open|stick|slip.
void writeContactCsv(std::ostream& out, const Problem& problem, const SolveResult& result);

}  // namespace stc
