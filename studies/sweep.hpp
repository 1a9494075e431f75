#pragma once
// A parameter sweep (`stcontact sweep`, docs/sweep.md): one scene solved for every value of one key,
// each value twice: warm-started from the previous value's solution (and, for the a priori bases,
// its spatial modes), and cold (from s = 0, as an independent solve). The report's question: what
// does the warm start save over the whole sweep?
#include <optional>
#include <string>
#include <vector>

#include "stcontact/contact/contact_interface.hpp"
#include "stcontact/solver/solve_result.hpp"
#include "stcontact/studies/run_environment.hpp"

namespace stc {

/// The cost and outcome of one solve.
struct SolveCost {
  Termination termination = Termination::MaxIterations;
  int iterations = 0;
  int relaxations = 0;          ///< fine LATIN relaxations
  long sparse_solves = 0;       ///< right-hand sides solved with the sparse factor
  double wall_s = 0.0;          ///< the whole call to solve, set-up (factorisation, basis) included
  double indicator = 0.0;       ///< final indicator (docs/method.md §2 η)
  std::optional<double> error;  ///< true error against this value's incremental solution (docs/method.md §2)

  bool converged() const { return termination == Termination::Converged; }
};

/// What a solve cost, from its summary (the true error is the caller's to add).
SolveCost costOf(const SolveSummary& summary, double wall_s);

/// Total contact forces on the body at the last instant (as reactions.csv's last row).
struct EndForces {
  double normal = 0.0;      ///< Σ_i λ_n,i (positive in compression)
  double tangential = 0.0;  ///< Σ_i λ_t,i (along τ_1, the first tangent of the frame)
};
EndForces endForces(const ContactInterface& contact, const InterfaceHistory& s);

/// How a warm solve began.
enum class WarmStart {
  Previous,  ///< from the previous value's solution (and interface directions)
  Zero,      ///< from s = 0: the first value, or the previous one had other sizes (mesh, time grid)
};
const char* toString(WarmStart start);

struct SweepPoint {
  std::string text;          ///< the value as written into the override
  double value = 0.0;
  WarmStart start = WarmStart::Zero;
  int seed_modes = 0;        ///< interface directions offered to the warm solve as its starting basis
                             ///< (fas-apriori, latin-pgd: SolveResult::interface_directions)
  SolveCost warm;
  std::optional<SolveCost> cold;  ///< absent with --no-independent
  EndForces forces;          ///< of the warm solve's solution
  double reference_s = 0.0;  ///< this value's incremental reference and error measure (not counted)
};

/// Sums over the sweep's values.
struct SweepTotals {
  int values = 0;
  int converged = 0;
  long relaxations = 0;
  long sparse_solves = 0;
  double wall_s = 0.0;
};

struct Sweep {
  std::string scene_name, scene_file;
  std::string command;  ///< the command line that produced it
  std::string key;      ///< the swept scene key, e.g. "contact.friction"
  std::string solver;
  double tolerance = 0.0;
  int n_dofs = 0, n_contact_nodes = 0, n_steps = 0;  ///< of the first value's problem
  std::vector<SweepPoint> points;
  RunEnvironment environment;
  std::string load_after;  ///< load averages when the runs ended

  bool independent() const { return !points.empty() && points.front().cold.has_value(); }
};

SweepTotals warmTotals(const Sweep& sweep);
/// Absent when the sweep has no cold solves (--no-independent).
std::optional<SweepTotals> coldTotals(const Sweep& sweep);
/// The largest true error of the warm solves; absent when none is known.
std::optional<double> largestWarmError(const Sweep& sweep);

}  // namespace stc
