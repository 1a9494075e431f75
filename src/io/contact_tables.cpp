#include "src/io/contact_tables.hpp"

#include <algorithm>
#include <limits>

#include "src/contact/contact_state_table.hpp"

namespace stc {
namespace {


// contact.csv of a 3D scene: the 2D columns with z and the second tangential components.
void writeContactCsv3d(std::ostream& out, const Problem& problem, const SolveResult& result) {
  const auto& c = problem.contact;
  const auto& s = result.interface;
  const auto& x = problem.solid.nodes;
  const ContactStateTable states(problem.contact, result.admissible());
  out.precision(12);
  out << "step,node,x,y,z,normal_force,tangential_force,tangential_force_2,pressure,shear,shear_2,gap,slip,slip_2,"
         "state\n";
  for (int k = 0; k < problem.numSteps(); ++k)
    for (int i = 0; i < c.size(); ++i) {
      const int n = 3 * i, node = c.nodes[i];
      const double area = c.tributary[i];
      const Eigen::Vector2d lt = s.lambda.col(k).segment<2>(n + 1);
      Eigen::Vector2d slip = s.v.col(k).segment<2>(n + 1);
      if (k > 0) slip -= s.v.col(k - 1).segment<2>(n + 1);
      out << k << ',' << node << ',' << x(0, node) << ',' << x(1, node) << ',' << x(2, node) << ','
          << s.lambda(n, k) << ',' << lt[0] << ',' << lt[1] << ',' << s.lambda(n, k) / area << ',' << lt[0] / area
          << ',' << lt[1] / area << ',' << c.initial_gap[i] + s.v(n, k) << ',' << slip[0] << ',' << slip[1] << ','
          << toString(states.state(i, k)) << '\n';
    }
}

}  // namespace

ReactionTable reactionTable(const Problem& problem, const SolveResult& result) {
  const auto& c = problem.contact;
  const auto& lambda = result.interface.lambda;
  const ContactStateTable states(problem.contact, result.admissible());
  const Eigen::MatrixXd x = problem.nodePositions();
  const int d = c.dimension;
  ReactionTable table;
  for (int k = 0; k < problem.numSteps(); ++k) {
    double normal = 0.0, tangential = 0.0, tangential_2 = 0.0;
    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin;
    int closed = 0, slipping = 0;
    for (int i = 0; i < c.size(); ++i) {
      normal += lambda(d * i, k);
      tangential += lambda(d * i + 1, k);
      if (d == 3) tangential_2 += lambda(d * i + 2, k);
      const ContactState state = states.state(i, k);
      if (state == ContactState::Open) continue;
      ++closed;
      slipping += state == ContactState::Slip;
      xmin = std::min(xmin, x(0, c.nodes[i]));
      xmax = std::max(xmax, x(0, c.nodes[i]));
    }
    if (closed == 0) xmin = xmax = std::numeric_limits<double>::quiet_NaN();
    table.t.push_back(problem.times[k]);
    table.normal_force.push_back(normal);
    table.tangential_force.push_back(tangential);
    if (d == 3) table.tangential_force_2.push_back(tangential_2);
    table.contact_xmin.push_back(xmin);
    table.contact_xmax.push_back(xmax);
    table.n_contact.push_back(closed);
    table.n_slip.push_back(slipping);
  }
  return table;
}

void writeReactionsCsv(std::ostream& out, const Problem& problem, const SolveResult& result) {
  const ReactionTable table = reactionTable(problem, result);
  out.precision(12);
  const bool three_d = problem.dimension == 3;
  out << "step,t,normal_force,tangential_force," << (three_d ? "tangential_force_2," : "")
      << "contact_xmin,contact_xmax,n_contact,n_slip\n";
  for (std::size_t k = 0; k < table.t.size(); ++k) {
    out << k << ',' << table.t[k] << ',' << table.normal_force[k] << ',' << table.tangential_force[k] << ',';
    if (three_d) out << table.tangential_force_2[k] << ',';
    if (table.n_contact[k] > 0) out << table.contact_xmin[k] << ',' << table.contact_xmax[k];
    else out << ',';
    out << ',' << table.n_contact[k] << ',' << table.n_slip[k] << '\n';
  }
}

void writeContactCsv(std::ostream& out, const Problem& problem, const SolveResult& result) {
  if (problem.dimension == 3) return writeContactCsv3d(out, problem, result);
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
