#include "src/io/contact_tables.hpp"

#include <algorithm>
#include <limits>

#include "src/contact/contact_state_table.hpp"

namespace stc {


void writeReactionsCsv(std::ostream& out, const Problem& problem, const SolveResult& result) {
  const auto& c = problem.contact;
  const auto& lambda = result.interface.lambda;
  const ContactStateTable states(problem.contact, result.admissible());
  out.precision(12);
  out << "step,t,normal_force,tangential_force,contact_xmin,contact_xmax,n_contact,n_slip\n";
  for (int k = 0; k < problem.numSteps(); ++k) {
    double normal = 0.0, tangential = 0.0;
    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin;
    int closed = 0, slipping = 0;
    for (int i = 0; i < c.size(); ++i) {
      normal += lambda(2 * i, k);
      tangential += lambda(2 * i + 1, k);
      const ContactState state = states.state(i, k);
      if (state == ContactState::Open) continue;
      ++closed;
      slipping += state == ContactState::Slip;
      xmin = std::min(xmin, problem.mesh.nodes(0, c.nodes[i]));
      xmax = std::max(xmax, problem.mesh.nodes(0, c.nodes[i]));
    }
    out << k << ',' << problem.times[k] << ',' << normal << ',' << tangential << ',';
    if (closed > 0) out << xmin << ',' << xmax;
    else out << ',';
    out << ',' << closed << ',' << slipping << '\n';
  }
}

void writeContactCsv(std::ostream& out, const Problem& problem, const SolveResult& result) {
  const auto& c = problem.contact;
  const auto& s = result.interface;
  const ContactStateTable states(problem.contact, result.admissible());
  out.precision(12);
  out << "step,node,x,y,normal_force,tangential_force,pressure,shear,gap,slip,state\n";
  for (int k = 0; k < problem.numSteps(); ++k)
    for (int i = 0; i < c.size(); ++i) {
      const double ln = s.lambda(2 * i, k), lt = s.lambda(2 * i + 1, k);
      out << k << ',' << c.nodes[i] << ',' << problem.mesh.nodes(0, c.nodes[i]) << ','
          << problem.mesh.nodes(1, c.nodes[i]) << ',' << ln << ',' << lt << ',' << ln / c.tributary[i] << ','
          << lt / c.tributary[i] << ',' << c.initial_gap[i] + s.v(2 * i, k) << ','
          << s.v(2 * i + 1, k) - (k > 0 ? s.v(2 * i + 1, k - 1) : 0.0) << ',' << toString(states.state(i, k)) << '\n';
    }
}

}  // namespace stc
