#pragma once
// The scene's [solver] table: which strategy, the search direction's scale, and the options of every
// strategy, each in its own struct (declared, defaulted and range-checked there, src/options/*.hpp).
// A key shared by several strategies (tolerance, max_iterations, pre_relaxations, pgd_gap_share…)
// sets the field in each: the scene reader walks every struct's fields.
#include "stcontact/options/fas_aposteriori_options.hpp"
#include "stcontact/options/fas_apriori_options.hpp"
#include "stcontact/options/incremental_options.hpp"
#include "stcontact/options/latin_options.hpp"
#include "stcontact/options/latin_pgd_options.hpp"
#include "stcontact/options/option_fields.hpp"
#include "stcontact/options/search_law.hpp"
#include "stcontact/options/strategy.hpp"

namespace stc {

struct SolverSpec {
  Strategy strategy = Strategy::FasApriori;  ///< solver.name
  /// κ of the search direction k = κ E ℓ_i / L (docs/method.md §2), a property of the problem every
  /// LATIN-based strategy iterates on; 4 from docs/search_direction.md.
  double search_scale = 4.0;
  /// How k is spread over the nodes (src/options/search_law.hpp): the local law, which is the
  /// tributary one where every contact facet has one size and follows the facet size on graded meshes
  /// (docs/search_direction.md "The local law").
  SearchLaw search_law = SearchLaw::Local;
  latin::LatinOptions latin;
  pgd::LatinPgdOptions latin_pgd;
  fas::FasAposterioriOptions fas_aposteriori;
  fas::FasAprioriOptions fas_apriori;
  IncrementalOptions incremental;

  template <class Self, class Visit>
  static void fields(Self& o, Visit&& visit) {
    visit("search_scale", o.search_scale, positive());
    visit("search_law", o.search_law, Keywords<SearchLaw>(kSearchLaws));
    latin::LatinOptions::fields(o.latin, visit);
    pgd::LatinPgdOptions::fields(o.latin_pgd, visit);
    fas::FasAposterioriOptions::fields(o.fas_aposteriori, visit);
    fas::FasAprioriOptions::fields(o.fas_apriori, visit);
    IncrementalOptions::fields(o.incremental, visit);
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
  void validate() const;  ///< every strategy's options
};

}  // namespace stc
