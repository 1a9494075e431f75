#include "stcontact/io/contact_tables.hpp"

#include <algorithm>
#include <limits>

#include "stcontact/io/text_buffer.hpp"
#include "stcontact/spacetime/contact_state_table.hpp"

namespace stc {
namespace {

constexpr int kCsvDigits = 12;                ///< significant digits of the CSV tables
constexpr std::size_t kFlushBytes = 1 << 20;  ///< contact.csv is written by pieces of about this size

}  // namespace

ReactionTable reactionTable(const Problem& problem, const SolveResult& result) {
  const auto& c = problem.contact;
  const auto& lambda = result.interface.lambda;
  const ContactStateTable states(problem.contact, result.admissible());
  const Eigen::MatrixXd x = problem.nodePositions();
  const int d = c.dimension;
  ReactionTable table;
  table.force = Eigen::MatrixXd::Zero(d, problem.numSteps());
  for (int k = 0; k < problem.numSteps(); ++k) {
    double normal = 0.0, tangential = 0.0, tangential_2 = 0.0;
    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin;
    int closed = 0, slipping = 0;
    for (int i = 0; i < c.size(); ++i) {
      normal += lambda(d * i, k);
      tangential += lambda(d * i + 1, k);
      if (d == 3) tangential_2 += lambda(d * i + 2, k);
      table.force.col(k) += inGlobalFrame(c, i, lambda.col(k).segment(c.normalRow(i), d));
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
  out.precision(kCsvDigits);
  const bool three_d = problem.dimension == 3;
  out << "step,t,normal_force,tangential_force," << (three_d ? "tangential_force_2," : "")
      << "contact_xmin,contact_xmax,n_contact,n_slip,force_x,force_y" << (three_d ? ",force_z" : "") << '\n';
  for (std::size_t k = 0; k < table.t.size(); ++k) {
    out << k << ',' << table.t[k] << ',' << table.normal_force[k] << ',' << table.tangential_force[k] << ',';
    if (three_d) out << table.tangential_force_2[k] << ',';
    if (table.n_contact[k] > 0) out << table.contact_xmin[k] << ',' << table.contact_xmax[k];
    else out << ',';
    out << ',' << table.n_contact[k] << ',' << table.n_slip[k];
    for (Eigen::Index a = 0; a < table.force.rows(); ++a) out << ',' << table.force(a, static_cast<Eigen::Index>(k));
    out << '\n';
  }
}

void writeContactCsv(std::ostream& out, const Problem& problem, const SolveResult& result) {
  const auto& c = problem.contact;
  const auto& s = result.interface;
  const int d = c.dimension;
  const Eigen::MatrixXd x = problem.nodePositions();
  const ContactStateTable states(problem.contact, result.admissible());
  // Columns for d = 2; in 3D the position gains z and each tangential quantity its τ_2 component.
  const bool three_d = d == 3;
  out << "step,node,x,y," << (three_d ? "z," : "") << "normal_force,tangential_force,"
      << (three_d ? "tangential_force_2," : "") << "pressure,shear," << (three_d ? "shear_2," : "") << "gap,slip,"
      << (three_d ? "slip_2," : "") << "state\n";
  TextBuffer row;
  const auto field = [&row](double value) { row.put(',').number(value, kCsvDigits); };
  for (int k = 0; k < problem.numSteps(); ++k) {
    for (int i = 0; i < c.size(); ++i) {
      const int n = c.normalRow(i), node = c.nodes[i];
      const double ln = s.lambda(n, k);
      row.integer(k).put(',').integer(node);
      for (int a = 0; a < d; ++a) field(x(a, node));
      field(ln);
      for (int a = 1; a < d; ++a) field(s.lambda(n + a, k));
      field(ln / c.tributary[i]);
      for (int a = 1; a < d; ++a) field(s.lambda(n + a, k) / c.tributary[i]);
      field(c.initial_gap[i] + s.v(n, k));
      for (int a = 1; a < d; ++a) field(s.v(n + a, k) - (k > 0 ? s.v(n + a, k - 1) : 0.0));
      row.put(',').text(toString(states.state(i, k))).put('\n');
    }
    if (row.size() > kFlushBytes) row.flushTo(out);
  }
  row.flushTo(out);
}

}  // namespace stc
