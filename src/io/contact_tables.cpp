#include "stcontact/io/contact_tables.hpp"

#include <algorithm>
#include <limits>

#include "stcontact/core/threads.hpp"
#include "stcontact/io/text_buffer.hpp"
#include "stcontact/spacetime/contact_state_table.hpp"

namespace stc {
namespace {

constexpr int kCsvDigits = 12;                ///< significant digits of the CSV tables
constexpr std::size_t kFlushBytes = 1 << 20;  ///< contact.csv is written by pieces of about this size

}  // namespace

ReactionTable reactionTable(const Problem& problem, const SolveResult& result) {
  return reactionTable(problem, result, interfaceTable(problem, result));
}

ReactionTable reactionTable(const Problem& problem, const SolveResult& result, const InterfaceTable& interface) {
  const auto& c = problem.contact;
  const auto& lambda = result.interface.lambda;
  const Eigen::MatrixXd x = problem.nodePositions();
  const int d = c.dimension, m = problem.numSteps();
  const auto steps = static_cast<std::size_t>(m);
  ReactionTable table;
  table.force = Eigen::MatrixXd::Zero(d, m);
  table.t = problem.times;
  table.normal_force.resize(steps);
  table.tangential_force.resize(steps);
  if (d == 3) table.tangential_force_2.resize(steps);
  table.contact_xmin.resize(steps);
  table.contact_xmax.resize(steps);
  table.n_contact.resize(steps);
  table.n_slip.resize(steps);
  parallelFor(m, threadCount(), [&](int k, int) {  // each instant its own entries
    const auto at = static_cast<std::size_t>(k);
    double normal = 0.0, tangential = 0.0, tangential_2 = 0.0;
    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin;
    int closed = 0, slipping = 0;
    const double* l = lambda.col(k).data();
    double resultant[3] = {0.0, 0.0, 0.0};  // Σ_i λ_n,i n_i + Σ_a λ_t,a,i τ_a,i (inGlobalFrame, summed)
    for (int i = 0; i < c.size(); ++i) {
      const double* node = l + c.normalRow(i);
      normal += node[0];
      tangential += node[1];
      if (d == 3) tangential_2 += node[2];
      for (int r = 0; r < d; ++r) {
        double sum = node[0] * c.normals(r, i);
        for (int a = 1; a < d; ++a) sum += node[a] * c.tangents(r, static_cast<Eigen::Index>(d - 1) * i + a - 1);
        resultant[r] += sum;
      }
      const auto state = static_cast<ContactState>(interface.state[at * static_cast<std::size_t>(c.size()) + static_cast<std::size_t>(i)]);
      if (state == ContactState::Open) continue;
      ++closed;
      slipping += state == ContactState::Slip;
      xmin = std::min(xmin, x(0, c.nodes[i]));
      xmax = std::max(xmax, x(0, c.nodes[i]));
    }
    if (closed == 0) xmin = xmax = std::numeric_limits<double>::quiet_NaN();
    for (int r = 0; r < d; ++r) table.force(r, k) = resultant[r];
    table.normal_force[at] = normal;
    table.tangential_force[at] = tangential;
    if (d == 3) table.tangential_force_2[at] = tangential_2;
    table.contact_xmin[at] = xmin;
    table.contact_xmax[at] = xmax;
    table.n_contact[at] = closed;
    table.n_slip[at] = slipping;
  });
  return table;
}

void writeReactionsCsv(std::ostream& out, const Problem& problem, const SolveResult& result) {
  writeReactionsCsv(out, problem, reactionTable(problem, result));
}

void writeReactionsCsv(std::ostream& out, const Problem& problem, const ReactionTable& table) {
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

InterfaceTable interfaceTable(const Problem& problem, const SolveResult& result) {
  const auto& c = problem.contact;
  const auto& s = result.interface;
  const int d = c.dimension, m = problem.numSteps(), n_c = c.size();
  const ContactStateTable states = result.contactStates(problem.contact);
  InterfaceTable table{m, n_c, d - 1, {}, {}, {}};
  if (m == 0 || n_c == 0) return table;
  const std::size_t cells = static_cast<std::size_t>(m) * static_cast<std::size_t>(n_c);
  table.gap.resize(cells);
  table.state.resize(cells);
  table.slip.resize(cells * static_cast<std::size_t>(d - 1));
  parallelFor(m, threadCount(), [&](int k, int) {
    for (int i = 0; i < n_c; ++i) {
      const std::size_t at = static_cast<std::size_t>(k) * static_cast<std::size_t>(n_c) + static_cast<std::size_t>(i);
      const int n = c.normalRow(i);
      const ContactState state = states.state(i, k);
      table.gap[at] = c.initial_gap[i] + s.v(n, k);
      table.state[at] = static_cast<std::int8_t>(state);
      for (int a = 1; a < d; ++a) {
        const std::size_t t = at * static_cast<std::size_t>(d - 1) + static_cast<std::size_t>(a - 1);
        table.slip[t] = state == ContactState::Open ? 0.0 : s.v(n + a, k) - (k > 0 ? s.v(n + a, k - 1) : 0.0);
      }
    }
  });
  return table;
}

double contactCsvBytes(const Problem& problem) {
  const double columns = 3.0 + problem.dimension + 3.0 * problem.dimension;  // step, t, node, x, forces, ...
  return 14.0 * columns * problem.numSteps() * problem.contact.size();        // about 14 characters a value
}

void writeContactCsv(std::ostream& out, const Problem& problem, const SolveResult& result, const InterfaceTable& table) {
  const auto& c = problem.contact;
  const auto& lambda = result.interface.lambda;
  const int d = c.dimension;
  const Eigen::MatrixXd x = problem.nodePositions();
  const std::vector<long long> tags = nodeTags(problem.body);  // what the user knows each node by
  // Columns for d = 2; in 3D the position gains z and each tangential quantity its τ_2 component.
  const bool three_d = d == 3;
  out << "step,t,node,x,y," << (three_d ? "z," : "") << "normal_force,tangential_force,"
      << (three_d ? "tangential_force_2," : "") << "pressure,shear," << (three_d ? "shear_2," : "") << "gap,slip,"
      << (three_d ? "slip_2," : "") << "state\n";
  TextBuffer row;
  const auto field = [&row](double value) { row.put(',').number(value, kCsvDigits); };
  for (int k = 0; k < problem.numSteps(); ++k) {
    for (int i = 0; i < c.size(); ++i) {
      const std::size_t at = static_cast<std::size_t>(k) * static_cast<std::size_t>(c.size()) + static_cast<std::size_t>(i);
      const std::size_t tangential = at * static_cast<std::size_t>(d - 1);
      const int n = c.normalRow(i), node = c.nodes[i];
      row.integer(k);
      field(problem.times[k]);
      row.put(',').integer(tags[static_cast<std::size_t>(node)]);
      for (int a = 0; a < d; ++a) field(x(a, node));
      for (int a = 0; a < d; ++a) field(lambda(n + a, k));
      for (int a = 0; a < d; ++a) field(lambda(n + a, k) / c.tributary[i]);  // pressure, shear(s)
      field(table.gap[at]);
      for (int a = 0; a < d - 1; ++a) field(table.slip[tangential + static_cast<std::size_t>(a)]);
      row.put(',').text(toString(static_cast<ContactState>(table.state[at]))).put('\n');
    }
    if (row.size() > kFlushBytes) row.flushTo(out);
  }
  row.flushTo(out);
}

}  // namespace stc
