#pragma once
// compare_bases's like-for-like runs and ablation (docs/compare_bases.md, "Like for like"): the a
// priori and the a posteriori basis on the same fine level with coarse spaces of equal size (the
// a posteriori SVD modes + residual vectors as many as the a priori energy modes + modes of the
// change), on the reduced interface and on the whole one, the seed paper's full-order FAS beside
// them, and `fas-apriori` with one ingredient off at a time. Each is the run a user makes: a solve at
// the tolerance τ that stops on its own estimate, its true error at termination beside it; the
// variants are timed alternated, medians over the repeats.
#include <iomanip>
#include <ostream>
#include <string>
#include <vector>

#include "stcontact/strategies/registry.hpp"
#include "stcontact/studies/programs/study_program.hpp"
#include "stcontact/studies/work_precision.hpp"

namespace stc::study {

struct Variant {
  std::string label;    ///< what runs
  std::string removes;  ///< against fas-apriori's default: what this variant changes ("" for the default)
  Strategy strategy;
  SolverSpec spec;
};

struct VariantRun {
  Variant variant;
  SolveSummary summary;  ///< the run with the true error at every relaxation
  double median_s = 0.0; ///< median wall time of the timed runs (no true error)
};

/// The variants, from the scene's solver settings at tolerance τ.
inline std::vector<Variant> likeForLikeVariants(const SolverSpec& scene_spec, double tau) {
  SolverSpec base = scene_spec;
  base.setTolerance(tau);
  base.fas_aposteriori.basis.svd_modes = base.fas_apriori.basis.modes;  // equal coarse-space size
  base.fas_aposteriori.basis.residual_vectors = base.fas_apriori.basis.increment_modes;
  base.fas_aposteriori.stage = base.fas_apriori.stage;
  base.fas_aposteriori.zone = base.fas_apriori.zone;
  base.fas_aposteriori.nested = base.fas_apriori.nested;
  base.fas_aposteriori.fine_level = fas::AposterioriFineLevel::Separated;
  auto with = [&](auto&& change) {
    SolverSpec s = base;
    change(s);
    return s;
  };
  const auto whole = [](SolverSpec& s) { s.fas_apriori.zone.enabled = s.fas_aposteriori.zone.enabled = false; };
  return {
      {"a priori, separated, reduced interface", "", Strategy::FasApriori, base},
      {"a posteriori, separated, reduced interface", "the basis (SVD of the converged solution + residual vectors)",
       Strategy::FasAposteriori, base},
      {"a priori, separated, whole interface", "the reduced interface", Strategy::FasApriori, with(whole)},
      {"a posteriori, separated, whole interface", "the basis and the reduced interface", Strategy::FasAposteriori,
       with(whole)},
      {"a posteriori, full order (seed paper)", "the basis, the reduced interface and the separated stage",
       Strategy::FasAposteriori, with([&](SolverSpec& s) {
         whole(s);
         s.fas_aposteriori.fine_level = fas::AposterioriFineLevel::Full;
       })},
      {"a priori, without the anticipated expansion", "the anticipated expansion", Strategy::FasApriori,
       with([](SolverSpec& s) { s.fas_apriori.basis.anticipate = false; })},
      {"a priori, without nested iteration in time", "nested iteration in time", Strategy::FasApriori,
       with([](SolverSpec& s) { s.fas_apriori.nested.instants = 0; })},
      {"incremental (the yardstick)", "another method: Newton in each instant, marching in time",
       Strategy::Incremental, base},
  };
}

/// Each variant once with the true error (`with_error`), then `repeats` rounds of timed runs
/// (`timed`), the variants alternated within a round.
inline std::vector<VariantRun> runAlternated(const Problem& problem, const std::vector<Variant>& variants,
                                             const SolveInputs& with_error, const SolveInputs& timed, int repeats) {
  std::vector<VariantRun> runs;
  for (const Variant& v : variants) runs.push_back({v, solve(v.strategy, problem, v.spec, with_error).summary, 0.0});
  std::vector<std::vector<double>> times(variants.size());
  for (int r = 0; r < repeats; ++r)
    for (std::size_t i = 0; i < variants.size(); ++i)
      times[i].push_back(solve(variants[i].strategy, problem, variants[i].spec, timed).summary.wall_s);
  for (std::size_t i = 0; i < runs.size(); ++i) runs[i].median_s = median(times[i]);
  return runs;
}

/// The relaxations of the first record at or below `target` ("·" when none).
inline std::string relaxationsTo(const SolveSummary& s, double target) {
  const IterationRecord* h = firstRecordBelow(s, target);
  return h ? std::to_string(h->relaxations) : "·";
}

inline int largestCoarseSpace(const SolveSummary& s) {
  int r = 0;
  for (const IterationRecord& h : s.history) r = std::max(r, h.rank);
  return r;
}

/// The table of the runs: the first is the reference of the time ratios, the last the incremental solver's.
inline void writeVariantTable(std::ostream& md, const std::vector<VariantRun>& runs) {
  const double incremental_s = runs.back().median_s;
  md << "| variant | changes against the first row | termination | relaxations | sparse solves | largest coarse space"
        " | estimate | true error | wall (s) | ÷ first row | ÷ incremental | relaxations to 1e-4 / 1e-6 (first reach) |\n"
        "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  const double first_s = runs.front().median_s;
  for (const VariantRun& r : runs) {
    const SolveSummary& s = r.summary;
    md << "| " << r.variant.label << " | " << (r.variant.removes.empty() ? "·" : r.variant.removes) << " | "
       << toString(s.termination) << " | ";
    if (r.variant.strategy == Strategy::Incremental)
      md << "· | " << s.sparseSolves() << " | · | · | 0 (the reference) | ";
    else
      md << s.relaxations << " | " << s.sparseSolves() << " | " << largestCoarseSpace(s) << " | "
         << std::setprecision(2) << s.error_estimate << " | " << s.error.value_or(NAN) << " | ";
    md << std::setprecision(3) << r.median_s << " | " << std::setprecision(2) << r.median_s / first_s << " | "
       << r.median_s / incremental_s << " | " << relaxationsTo(s, 1e-4) << " / " << relaxationsTo(s, 1e-6) << " |\n";
  }
}

}  // namespace stc::study
