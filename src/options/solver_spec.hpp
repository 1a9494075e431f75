#pragma once
// The scene's [solver] table: which strategy, and the options of every strategy, each in its own
// struct (declared, defaulted and range-checked there, src/options/*.hpp). The table's two other
// keys, the search direction's (search_direction_options.hpp), belong to the model.
// A key shared by several strategies (tolerance, max_iterations, pre_relaxations, pgd_gap_share…)
// sets the field in each: the scene reader walks every struct's fields.
#include "stcontact/options/fas_aposteriori_options.hpp"
#include "stcontact/options/fas_apriori_options.hpp"
#include "stcontact/options/incremental_options.hpp"
#include "stcontact/options/latin_options.hpp"
#include "stcontact/options/latin_pgd_options.hpp"
#include "stcontact/options/linear_solver_options.hpp"
#include "stcontact/options/option_fields.hpp"
#include "stcontact/options/strategy.hpp"

namespace stc {

struct SolverSpec {
  Strategy strategy = Strategy::FasApriori;  ///< solver.name
  latin::LatinOptions latin;
  pgd::LatinPgdOptions latin_pgd;
  fas::FasAposterioriOptions fas_aposteriori;
  fas::FasAprioriOptions fas_apriori;
  IncrementalOptions incremental;
  /// The engine under every strategy: which backend prepares and solves the sparse operators
  /// (solver.linear, solver.linear_rtol, solver.linear_max_iterations).
  LinearSolverOptions linear;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    latin::LatinOptions::fields(o.latin, visit);
    pgd::LatinPgdOptions::fields(o.latin_pgd, visit);
    fas::FasAposterioriOptions::fields(o.fas_aposteriori, visit);
    fas::FasAprioriOptions::fields(o.fas_apriori, visit);
    IncrementalOptions::fields(o.incremental, visit);
    LinearSolverOptions::fields(o.linear, visit);
  }
  /// The strategy's name ("fas-apriori").
  std::string_view name() const { return nameOf(strategy); }
  /// The stopping options of `s` (of the iterative strategies; null for `incremental`).
  StoppingOptions* stopping(Strategy s);
  const StoppingOptions* stopping(Strategy s) const;
  /// solver.tolerance and solver.max_iterations for every iterative strategy, as the scene keys set
  /// them (the command line's --tol and --max-iterations of a study).
  void setTolerance(double tolerance);
  void setMaxIterations(int max_iterations);
  /// The tolerance of the strategy named (of `latin` for `incremental`, which has none): the scene's
  /// solver.tolerance unless a library caller set the strategies apart.
  double tolerance() const;
  /// `linear` with its residual tolerance set from tolerance() (LinearSolverOptions::residualTolerance).
  /// InputError when linear.rtol is looser than 1e-4 tolerance(): "converged" could be wrong.
  LinearSolverOptions linearAtTolerance() const;
  void validate() const;  ///< every strategy's options
};

}  // namespace stc
