#include "stcontact/studies/sweep_writer.hpp"

#include <cmath>
#include <sstream>

#include "stcontact/io/atomic_file.hpp"
#include "stcontact/studies/number_format.hpp"

namespace stc {
namespace {

void costCells(std::ostream& out, const std::optional<SolveCost>& c) {
  if (!c) {
    out << ",,,,,,";
    return;
  }
  out << ',' << toString(c->termination) << ',' << c->relaxations << ',' << c->sparse_solves << ','
      << shortNumber(c->wall_s, 6) << ',' << shortNumber(c->indicator, 6) << ',' << shortNumber(c->error, 6);
}

/// |T| / N at the last instant: μ when the whole contact zone slides; empty without contact.
std::string forceRatio(const EndForces& f) {
  return f.normal > 0.0 ? shortNumber(std::abs(f.tangential) / f.normal, 6) : "";
}

std::string ratio(double warm, double cold) { return cold > 0.0 ? shortNumber(warm / cold, 3) : "—"; }

void introduction(std::ostream& out, const Sweep& s) {
  out << "# Parameter sweep: " << s.scene_name << ", " << s.key << "\n\n"
      << "Produced by `" << s.command << "`.\n\n"
      << "Scene `" << s.scene_file << "`: " << s.n_dofs << " dofs, " << s.n_contact_nodes << " contact nodes, "
      << s.n_steps << " instants (first value); solver `" << s.solver << "`, tolerance on the error estimate "
      << shortNumber(s.tolerance, 3) << "; " << s.points.size() << " values of `" << s.key << "`.\n\n"
      << "*Warm*: each value starts from the previous value's solution (interface history) and, for the "
         "separated global stages (latin-pgd, fas-apriori), its interface directions; the first value "
         "starts from zero. *Cold*: every value solved independently from zero. Each solve rebuilds the "
         "problem and its factorisation (the search direction and K + BᵀkB may depend on the value). Times: the whole solve call, set-up included; "
         "the problem's assembly and the incremental reference that gives the true error (docs/method.md §2) "
         "are not counted.\n\n";
}

void totalsTable(std::ostream& out, const Sweep& s) {
  const SweepTotals warm = warmTotals(s);
  const auto cold = coldTotals(s);
  out << "## Totals over the sweep\n\n| | relaxations | sparse solves | wall time | converged |\n|---|---|---|---|---|\n";
  const auto row = [&](const char* name, const SweepTotals& t) {
    out << "| " << name << " | " << t.relaxations << " | " << t.sparse_solves << " | " << shortNumber(t.wall_s, 3)
        << " s | " << t.converged << " of " << t.values << " |\n";
  };
  row("warm", warm);
  if (cold) {
    row("cold", *cold);
    out << "| warm ÷ cold | " << ratio(warm.relaxations, cold->relaxations) << " | "
        << ratio(warm.sparse_solves, cold->sparse_solves) << " | " << ratio(warm.wall_s, cold->wall_s) << " | |\n";
  }
  out << "\n";
}

void valueTable(std::ostream& out, const Sweep& s) {
  out << "## Per value\n\n| " << s.key
      << " | warm start | relaxations warm / cold | sparse solves warm / cold | wall s warm / cold "
         "| true error warm / cold | N end | T end | abs(T)/N end |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const SweepPoint& p : s.points) {
    const auto pair = [&](const std::string& w, const std::string& c) { return w + " / " + (p.cold ? c : "—"); };
    const SolveCost cold = p.cold.value_or(SolveCost{});
    out << "| " << p.text << " | " << toString(p.start) << (p.seed_modes ? ", " + std::to_string(p.seed_modes) + " directions offered" : "")
        << " | " << pair(std::to_string(p.warm.relaxations), std::to_string(cold.relaxations)) << " | "
        << pair(std::to_string(p.warm.sparse_solves), std::to_string(cold.sparse_solves)) << " | "
        << pair(shortNumber(p.warm.wall_s, 3), shortNumber(cold.wall_s, 3)) << " | "
        << pair(shortNumber(p.warm.error, 2), shortNumber(cold.error, 2)) << " | " << shortNumber(p.forces.normal, 5)
        << " | " << shortNumber(p.forces.tangential, 5) << " | " << forceRatio(p.forces) << " |\n";
  }
  out << "\n";
}

void notes(std::ostream& out, const Sweep& s) {
  out << "## Notes\n\n";
  if (const auto e = largestWarmError(s)) out << "- Largest true error of a warm solve: " << shortNumber(*e, 2) << ".\n";
  for (const SweepPoint& p : s.points) {
    if (!p.warm.converged()) out << "- " << s.key << " = " << p.text << ": warm solve " << toString(p.warm.termination) << ".\n";
    if (p.cold && !p.cold->converged())
      out << "- " << s.key << " = " << p.text << ": cold solve " << toString(p.cold->termination) << ".\n";
  }
  double reference_s = 0.0;
  for (const SweepPoint& p : s.points) reference_s += p.reference_s;
  out << "- Incremental references and error measures, all values: " << shortNumber(reference_s, 3)
      << " s, not counted.\n\n";
}

}  // namespace

std::string sweepCsv(const Sweep& s) {
  std::ostringstream out;
  out << "value,start,seed_modes,warm_termination,warm_relaxations,warm_sparse_solves,warm_wall_s,warm_indicator,"
         "warm_error,cold_termination,cold_relaxations,cold_sparse_solves,cold_wall_s,cold_indicator,cold_error,"
         "normal_force_end,tangential_force_end,tangential_over_normal_end,reference_s\n";
  for (const SweepPoint& p : s.points) {
    out << p.text << ',' << toString(p.start) << ',' << p.seed_modes;
    costCells(out, p.warm);
    costCells(out, p.cold);
    out << ',' << shortNumber(p.forces.normal, 10) << ',' << shortNumber(p.forces.tangential, 10) << ','
        << forceRatio(p.forces) << ',' << shortNumber(p.reference_s, 6) << '\n';
  }
  return out.str();
}

std::string sweepMarkdown(const Sweep& s) {
  std::ostringstream out;
  introduction(out, s);
  totalsTable(out, s);
  valueTable(out, s);
  notes(out, s);
  out << machineMarkdown(s.environment, s.load_after);
  return out.str();
}

void writeSweep(const std::filesystem::path& dir, const Sweep& sweep) {
  writeFileAtomically(dir / "sweep.csv", sweepCsv(sweep));
  writeFileAtomically(dir / "summary.md", sweepMarkdown(sweep));
}

}  // namespace stc
