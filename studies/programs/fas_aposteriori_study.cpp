// Description
//   Reproduces Figs. 4 and 5 of the seed paper (Giacoma et al., CSMA 2013, §4.2–4.3; docs/method.md §4):
//   the two-level FAS with LATIN as smoother and an a posteriori coarse space (leading energy-SVD
//   modes of the converged solution, docs/method.md §3, plus N_res residual vectors renewed every cycle,
//   seed §4.3) against plain LATIN on the seed scene. Every run records, per fine relaxation, the
//   LATIN indicator and the TRUE error (relative elastic energy over the grid against the incremental
//   solution, docs/method.md §2). Also: LATIN with ω = 0.95, SVD modes without residual vectors, the
//   coarse start (a) zero correction vs (b) interface mismatch, a few i_C, and the measured cost of
//   one coarse step against one fine relaxation (goal ≤ 10%). The search-direction scale κ is the
//   scene's solver.search_scale (override it with --set). Report: docs/fas_aposteriori.md.
// Sample run
//   build/bin/fas_aposteriori_study examples/scenes/hemicylinder.toml --set solver.search_scale=3
//   build/bin/fas_aposteriori_study --small --set solver.search_scale=3 --out /tmp/fas_small
// Options: [SCENE] (default: the seed scene), --out DIR (default results/fas_aposteriori),
//   --set KEY=VALUE (repeatable, passed to readScene), --small (mesh.arc_nodes=21, time.steps=21,
//   four runs: the ctest case examples.fas_aposteriori_study_small), --max-relaxations N (cap per
//   run, default 600), --safeguard (FAS with the coarse-step safeguard of FasOptions, the library
//   default, with i_C adapted to its verdicts; without it the seed's plain cycle, which its figures
//   show), --fixed-ic (with --safeguard: i_C fixed, FasOptions::adapt_coarse_iterations off, as in
//   version 0.2.0).
// Steps: 1 scene · 2 reference, true-error measure, SVD modes · 3 runs (one CSV each) ·
//   4 coarse-step cost · 5 figures (gnuplot) · 6 summary.md · 7 check: FAS (10 SVD + 15 RES,
//   ν = 2) reaches true error 1e-4 in fewer relaxations than LATIN.
// Exit status: 0 ok, 1 bad input, 2 the check of step 7 failed, 3 internal failure.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "stcontact/core/clock.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/fas/aposteriori/aposteriori_basis.hpp"
#include "stcontact/fas/aposteriori/fixed_basis_provider.hpp"
#include "stcontact/fas/coarse_step.hpp"
#include "stcontact/fas/fas_solver.hpp"
#include "stcontact/incremental/condensed_interface.hpp"
#include "stcontact/incremental/error_reference.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/latin/global_stage.hpp"
#include "stcontact/latin/indicator.hpp"
#include "stcontact/latin/latin_solver.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/studies/gnuplot_runner.hpp"
#include "stcontact/studies/programs/study_program.hpp"
#include "stcontact/studies/work_precision.hpp"

namespace fs = std::filesystem;
using stc::fas::CoarseStart;

namespace {

using Clock = std::chrono::steady_clock;
using stc::secondsSince;

constexpr double kStopError = 1e-8;  // a run stops once its true error is below this (callback)
constexpr int kMaxModes = 20;

struct Options : stc::study::StudyOptions {
  bool safeguard = false;  ///< --safeguard: FAS with the coarse-step safeguard (library default)
  bool fixed_ic = false;   ///< --fixed-ic: with the safeguard, i_C fixed (adapted by default)
  int max_relaxations = 600;
};

// ---- the runs ------------------------------------------------------------------------------

struct RunSpec {
  std::string name;   ///< CSV file stem
  std::string label;  ///< legend
  bool latin = false;
  double omega = 1.0;  ///< LATIN relaxation
  int modes = 0, res = 15, nu = 1;
  CoarseStart start = CoarseStart::ZeroCorrection;
  int ic = 15;  ///< i_C
};

RunSpec fasRun(int modes, int res, int nu, CoarseStart start = CoarseStart::ZeroCorrection, int ic = 15) {
  const bool b = start == CoarseStart::InterfaceMismatch;
  const std::string i = std::to_string(ic);
  std::string name = "fas_m" + std::to_string(modes) + "_r" + std::to_string(res) + "_nu" + std::to_string(nu);
  std::string label = std::to_string(modes) + " SVD" + (res ? " + " + std::to_string(res) + " RES" : ", no RES") +
                      ", nu=" + std::to_string(nu) + (b ? ", start (b)" : "") + (ic != 15 ? ", i_C=" + i : "");
  return {name + (b ? "_startb" : "") + (ic != 15 ? "_ic" + i : ""), label, false, 1.0, modes, res, nu, start, ic};
}

std::vector<RunSpec> studyRuns(bool small) {
  std::vector<RunSpec> runs = {{"latin", "LATIN", true}};
  if (small) {
    for (int nu : {1, 2}) runs.push_back(fasRun(10, 15, nu));
    runs.push_back(fasRun(10, 15, 2, CoarseStart::InterfaceMismatch));
    return runs;
  }
  runs.push_back({"latin_w095", "LATIN, omega=0.95", true, 0.95});
  for (int nu : {1, 2})
    for (int m : {2, 5, 10, 20}) runs.push_back(fasRun(m, 15, nu));  // Fig. 4 (ν = 1: the seed's)
  runs.push_back(fasRun(10, 15, 3));                                 // Fig. 5
  for (int nu : {1, 2})
    for (int m : {5, 20}) runs.push_back(fasRun(m, 0, nu));  // seed §4.3: SVD modes alone
  for (int nu : {1, 2}) runs.push_back(fasRun(10, 15, nu, CoarseStart::InterfaceMismatch));
  runs.push_back(fasRun(20, 0, 2, CoarseStart::ZeroCorrection, 1));  // is the no-RES stall the coarse iterations'?
  for (int ic : {3, 8, 30}) runs.push_back(fasRun(10, 15, 1, CoarseStart::ZeroCorrection, ic));  // cost lever
  return runs;
}

struct Study {
  stc::Scene scene;
  stc::Problem problem;
  std::unique_ptr<stc::ErrorReference> reference;
  Eigen::MatrixXd modes;  ///< n_free × (≤ kMaxModes) energy-SVD modes of the converged solution
  double incremental_s = 0.0, svd_s = 0.0;
  bool safeguard = false;  ///< FasOptions::safeguard (off: the seed's plain cycle, as in its figures)
  bool adapt = true;       ///< FasOptions::adapt_coarse_iterations (with the safeguard only)
};

stc::SolveResult runOne(const Study& st, const RunSpec& r, stc::latin::GlobalStage& global, int cap) {
  const stc::IterationCallback stop = [](const stc::IterationRecord& rec) {
    return !(rec.error && *rec.error <= kStopError);
  };
  if (r.latin) {
    stc::latin::LatinOptions o;
    o.stop = {1e-9, cap, 150};
    o.relaxation = r.omega;
    return stc::latin::solveLatinWith(st.problem, global, o, {.reference = st.reference.get(), .callback = stop},
                                      "latin");
  }
  stc::fas::FasOptions o;
  o.stop = {1e-9, cap, 150};
  o.pre_relaxations = o.post_relaxations = r.nu;
  o.coarse_iterations = r.ic;
  o.start = r.start;
  o.safeguard = st.safeguard;
  o.adapt_coarse_iterations = st.adapt;
  const int m = std::min<int>(r.modes, static_cast<int>(st.modes.cols()));
  global.keepDisplacements(true);
  stc::fas::FixedBasisProvider provider(st.modes.leftCols(m), r.res, global, st.problem.contact.B);
  return stc::fas::solveFas(st.problem, global, provider, o, {.reference = st.reference.get(), .callback = stop},
                            "fas-aposteriori");
}

// ---- statistics of one history ---------------------------------------------------------------

struct Stats {
  std::optional<int> to4, to6;      ///< relaxations to true error ≤ 1e-4, 1e-6
  std::optional<double> wall6;      ///< wall time to true error ≤ 1e-6
  std::optional<double> e_at_eta6;  ///< true error when the indicator first reaches 1e-6
  std::optional<double> ratio;      ///< median of error / indicator over records with 1e-8 < e < 1e-3
};

Stats statsOf(const stc::SolveSummary& s) {
  Stats st;
  std::vector<double> ratios;
  for (const auto& rec : s.history) {
    if (!rec.error) continue;
    const double e = *rec.error;
    if (!st.to4 && e <= 1e-4) st.to4 = rec.relaxations;
    if (!st.to6 && e <= 1e-6) st.to6 = rec.relaxations, st.wall6 = rec.wall_s;
    if (!st.e_at_eta6 && rec.indicator <= 1e-6) st.e_at_eta6 = e;
    if (e > 1e-8 && e < 1e-3 && rec.indicator > 0) ratios.push_back(e / rec.indicator);
  }
  if (!ratios.empty()) {
    std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
    st.ratio = ratios[ratios.size() / 2];
  }
  return st;
}

std::string sci(double x, int digits = 2) {
  std::ostringstream os;
  os << std::setprecision(digits) << x;
  return os.str();
}

std::string finalStatus(const stc::SolveSummary& s) {
  const std::string e = s.error ? sci(*s.error) : "?";
  if (s.termination == stc::Termination::StoppedByCallback) return "e <= 1e-8 at " + std::to_string(s.relaxations);
  return std::string(stc::toString(s.termination)) + " at " + std::to_string(s.relaxations) + ", e = " + e;
}

// ---- step 4: the cost of a coarse step against a fine relaxation ------------------------------

struct Cost {
  double relaxation_s = 0.0;  ///< GlobalStage::solve + indicator + localStage
  double local_s = 0.0;       ///< localStage alone (i_C of them in a coarse step)
  double error_s = 0.0;       ///< one true-error evaluation (in every run's wall time, not in FAS's cost)
  struct Row {
    int svd = 0, rank = 0;
    double renew_s = 0.0, coarse_s = 0.0;          ///< medians
    double renew_ratio = 0.0, coarse_ratio = 0.0;  ///< medians of the per-repeat ratios to the relaxation
  };
  std::vector<Row> rows;
};

// Every repeat times a relaxation, then each coarse space's renewal and coarse step, back to back, so
// that a burst of load on the machine hits the numerator and the denominator of a ratio alike.
Cost measureCost(const Study& st, stc::latin::GlobalStage& global, int repeats) {
  const auto& contact = st.problem.contact;
  stc::InterfaceHistory s = stc::InterfaceHistory::zeros(contact, st.problem.numSteps()), hat, s2, hat2;

  stc::latin::localStage(contact, s, hat);
  global.keepDisplacements(true);
  for (int i = 0; i < 10; ++i) {  // a realistic iterate: ten LATIN iterations in
    global.solve(hat, s);  // keeps ũ for the providers' residual vectors
    stc::latin::localStage(contact, s, hat);
  }
  std::vector<std::unique_ptr<stc::fas::FixedBasisProvider>> providers;
  std::vector<stc::fas::CoarseSpace> spaces;
  Cost c;
  for (int svd : {10, 20}) {
    const int m = std::min<int>(svd, static_cast<int>(st.modes.cols()));
    if (!c.rows.empty() && c.rows.back().svd == m) break;  // small scenes: fewer modes than asked
    providers.push_back(
        std::make_unique<stc::fas::FixedBasisProvider>(st.modes.leftCols(m), 15, global, contact.B));
    spaces.push_back(providers.back()->coarseSpace(hat));
    c.rows.push_back({m, spaces.back().rank()});
  }
  const stc::fas::FasOptions o;  // i_C = 15, start (a)
  std::vector<double> relax, local, error;
  std::vector<std::vector<double>> renew(c.rows.size()), coarse(c.rows.size()), rr(c.rows.size()), cr(c.rows.size());
  for (int i = 0; i < repeats; ++i) {
    relax.push_back(stc::study::secondsOf([&] {
      global.solve(hat, s2);
      volatile double eta = stc::latin::indicator(contact.search_direction, s2, hat);
      (void)eta;
      stc::latin::localStage(contact, s2, hat2);
    }));
    local.push_back(stc::study::secondsOf([&] { stc::latin::localStage(contact, s2, hat2); }));
    error.push_back(stc::study::secondsOf([&] {
      volatile double e = st.reference->relativeError(s2.lambda);
      (void)e;
    }));
    for (std::size_t j = 0; j < c.rows.size(); ++j) {
      renew[j].push_back(stc::study::secondsOf([&] { spaces[j] = providers[j]->coarseSpace(hat); }));
      hat2 = hat;  // coarseStep overwrites its local-stage iterate: start each repeat from the same one
      coarse[j].push_back(stc::study::secondsOf([&] { stc::fas::coarseStep(contact, spaces[j], o, s, hat2); }));
      rr[j].push_back(renew[j].back() / relax.back());
      cr[j].push_back(coarse[j].back() / relax.back());
    }
  }
  c.relaxation_s = stc::median(relax), c.local_s = stc::median(local), c.error_s = stc::median(error);
  for (std::size_t j = 0; j < c.rows.size(); ++j) {
    c.rows[j].renew_s = stc::median(renew[j]), c.rows[j].coarse_s = stc::median(coarse[j]);
    c.rows[j].renew_ratio = stc::median(rr[j]), c.rows[j].coarse_ratio = stc::median(cr[j]);
  }
  return c;
}

// ---- steps 5–6: files ------------------------------------------------------------------------

void writeCsv(const fs::path& file, const stc::SolveSummary& s) {
  std::ofstream f(file);
  f << "relaxation,indicator,error,wall_s,rank\n" << std::setprecision(6);
  for (const auto& r : s.history)
    f << r.relaxations << ',' << r.indicator << ',' << (r.error ? *r.error : std::nan("")) << ',' << r.wall_s << ','
      << r.rank << '\n';
}

struct Outcome {
  RunSpec spec;
  stc::SolveSummary summary;
  Stats stats;
};

std::string ratioCell(std::optional<int> latin, std::optional<int> run) {
  if (!latin || !run) return "·";
  return sci(static_cast<double>(*latin) / *run, 3);
}

std::string count(std::optional<int> n, int cap) { return n ? std::to_string(*n) : "> " + std::to_string(cap); }

void writeRunTable(std::ostream& md, const std::vector<Outcome>& all, int cap) {
  const Stats& latin = all.front().stats;
  md << "| run | relax. to e ≤ 1e-4 | LATIN ÷ run | relax. to e ≤ 1e-6 | LATIN ÷ run | wall to 1e-6 (s) | "
        "ms / relax. | final | median e/η | e when η ≤ 1e-6 |\n|---|---:|---:|---:|---:|---:|---:|---|---:|---:|\n";
  for (const auto& o : all) {
    const Stats& s = o.stats;
    md << "| " << o.spec.label << " | " << count(s.to4, cap) << " | " << ratioCell(latin.to4, s.to4) << " | "
       << count(s.to6, cap) << " | " << ratioCell(latin.to6, s.to6) << " | " << (s.wall6 ? sci(*s.wall6, 3) : "·")
       << " | " << sci(1e3 * o.summary.wall_s / std::max(1, o.summary.relaxations), 3) << " | "
       << finalStatus(o.summary) << " | " << (s.ratio ? sci(*s.ratio) : "·") << " | "
       << (s.e_at_eta6 ? sci(*s.e_at_eta6) : "·") << " |\n";
  }
}

void writeSummary(const fs::path& file, const Options& opt, const Study& st, const Cost& cost,
                  const std::vector<Outcome>& all, double total_s) {
  std::ofstream md(file);
  md << "# FAS a posteriori study (seed Figs. 4–5)\n\nScene `" << opt.scene.filename().string() << "`";
  for (const auto& s : opt.overrides) md << " `--set " << s << "`";
  md << ": " << st.problem.numDofs() << " dofs, " << st.problem.contact.size() << " contact nodes, "
     << st.problem.numSteps() << " instants, kappa = " << st.scene.search_direction.scale << ". Relaxation cap "
     << opt.max_relaxations << ", runs stop at true error <= 1e-8 or indicator <= 1e-9, "
     << "stagnation window 150; i_C = 15; FAS cycle "
     << (!opt.safeguard   ? "plain (the seed's, no safeguard)"
         : opt.fixed_ic ? "with the coarse-step safeguard, i_C fixed"
                        : "with the coarse-step safeguard, i_C adapted to it (at most 15)")
     << ".\n\n"
     << "Incremental reference: " << sci(st.incremental_s, 3)
     << " s. Energy SVD modes (a posteriori cost): " << sci(st.svd_s, 3) << " s. Whole study: " << sci(total_s, 3)
     << " s.\n\n"
     << "## Relaxations to TRUE error (relative energy, docs/method.md §2)\n\n";
  writeRunTable(md, all, opt.max_relaxations);
  md << "\n## Cost of one coarse step (i_C = 15) against one fine relaxation (" << opt.repeats
     << " interleaved repeats: medians of the times and of the per-repeat ratios)\n\nFine relaxation (global stage + "
        "indicator + local stage): "
     << sci(cost.relaxation_s * 1e3, 3) << " ms; one local stage alone: " << sci(cost.local_s * 1e3, 3)
     << " ms; one true-error evaluation (in "
     << "every run's wall time above, once per relaxation): " << sci(cost.error_s * 1e3, 3)
     << " ms.\n\n| SVD + RES | rank r | coarse step (ms) | ÷ relaxation | RES renewal + A-orthonormalisation (ms) | "
        "÷ relaxation | both ÷ relaxation |\n|---|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& r : cost.rows)
    md << "| " << r.svd << " + 15 | " << r.rank << " | " << sci(r.coarse_s * 1e3, 3) << " | " << sci(r.coarse_ratio, 2)
       << " | " << sci(r.renew_s * 1e3, 3) << " | " << sci(r.renew_ratio, 2) << " | "
       << sci(r.coarse_ratio + r.renew_ratio, 2) << " |\n";
}

struct Panel {
  std::string title;
  std::vector<std::string> runs;
  bool indicators = false;  ///< dashed indicator curves in the run's colour
  std::string key = "top right";
};
struct Figure {
  std::string file;
  std::vector<Panel> panels;
};

std::vector<Figure> figures(bool small) {
  if (small)
    return {{"fas_small.png",
             {{"small scene", {"latin", "fas_m10_r15_nu1", "fas_m10_r15_nu2", "fas_m10_r15_nu2_startb"}, true}}}};
  const std::vector<std::string> m4 = {"2", "5", "10", "20"};
  auto fig4 = [&](const std::string& nu) {
    Panel p{"FAS, SVD + 15 RES, nu1 = nu2 = " + nu + " (solid: true error)", {"latin"}};
    for (const auto& m : m4) p.runs.push_back("fas_m" + m + "_r15_nu" + nu);
    return p;
  };
  return {
      {"fas_fig4.png", {fig4("1"), fig4("2")}},
      {"fas_fig5.png",
       {{"10 SVD + 15 RES, nu1 = nu2 in {1, 2, 3} (dashed: indicator)",
         {"latin", "fas_m10_r15_nu1", "fas_m10_r15_nu2", "fas_m10_r15_nu3"},
         true},
        {"10 SVD + 15 RES, nu = 1: coarse iterations i_C",
         {"latin", "fas_m10_r15_nu1_ic3", "fas_m10_r15_nu1_ic8", "fas_m10_r15_nu1", "fas_m10_r15_nu1_ic30"}}}},
      {"fas_nores.png",
       {{"with / without residual vectors, nu = 1",
         {"latin", "fas_m5_r0_nu1", "fas_m20_r0_nu1", "fas_m5_r15_nu1", "fas_m20_r15_nu1"},
         false,
         "bottom center"},
        {"with / without residual vectors, nu = 2",
         {"latin", "fas_m5_r0_nu2", "fas_m20_r0_nu2", "fas_m5_r15_nu2", "fas_m20_r15_nu2", "fas_m20_r0_nu2_ic1"},
         false,
         "bottom center"}}},
      {"fas_start.png",
       {{"coarse start (a) zero vs (b) mismatch, 10 SVD + 15 RES (dashed: indicator)",
         {"latin", "fas_m10_r15_nu1", "fas_m10_r15_nu1_startb", "fas_m10_r15_nu2", "fas_m10_r15_nu2_startb"},
         true}}},
  };
}

std::string labelOf(const std::vector<Outcome>& all, const std::string& name) {
  for (const auto& o : all)
    if (o.spec.name == name) return o.spec.label;
  return name;
}

void writeGnuplot(const fs::path& file, const std::vector<Figure>& figs, const std::vector<Outcome>& all, int cap) {
  std::ofstream gp(file);
  gp << "# Written by fas_aposteriori_study: run with `gnuplot fas_study.gp` in this folder.\n"
     << "if (!exists('suffix')) suffix = ''\n"
     << "set datafile separator ','\nset logscale y\nset format y '1e%T'\nset grid\nset yrange [1e-9:3]\n"
     << "set xrange [0:" << std::min(cap, 200) << "]  # stalled runs go on to the cap in their CSV\n"
     << "set xlabel 'fine relaxations'\nset ylabel 'true error (relative energy)'\n"
     << "set key top right font ',8' opaque\n";
  for (const auto& f : figs) {
    gp << "set terminal pngcairo size " << 560 * f.panels.size() << ",440 font ',9' noenhanced\nset output '" << f.file
       << "'.suffix\nset multiplot layout 1," << f.panels.size() << "\n";
    for (const auto& p : f.panels) {
      gp << "set title '" << p.title << "'\nset key " << p.key << "\nplot ";
      for (std::size_t i = 0; i < p.runs.size(); ++i) {
        const std::string csv = "'" + p.runs[i] + ".csv' skip 1";
        gp << (i ? ", \\\n     " : "") << csv << " using 1:3 with lines lw 2 lc " << i + 1 << " title '"
           << labelOf(all, p.runs[i]) << "'";
        if (p.indicators) gp << ", \\\n     " << csv << " using 1:2 with lines lw 1 dt 2 lc " << i + 1 << " notitle";
      }
      gp << "\n";
    }
    gp << "unset multiplot\n";
  }
}

void drawFigures(const fs::path& out, const std::vector<Figure>& figs, const std::vector<Outcome>& all, int cap) {
  writeGnuplot(out / "fas_study.gp", figs, all, cap);
  std::vector<std::string> files;
  for (const auto& f : figs) files.push_back(f.file);
  const stc::PlotStatus status = stc::runPlots(out, {"fas_study.gp", "", files, false}).status;
  if (status == stc::PlotStatus::GnuplotMissing) {
    std::cout << "   gnuplot not found: figures skipped (CSV, summary.md and fas_study.gp are written)\n";
    return;
  }
  if (status != stc::PlotStatus::Drawn)
    std::cout << "   gnuplot failed (see its message above)\n";
  else
    for (const auto& f : figs) std::cout << "   " << (out / f.file).string() << "\n";
}

// ---- main steps --------------------------------------------------------------------------------

Study prepare(const Options& opt) {
  Study st;
  st.safeguard = opt.safeguard;
  st.adapt = !opt.fixed_ic;
  st.scene = stc::readScene(opt.scene, opt.overrides);
  st.problem = stc::buildProblem(st.scene);
  std::cout << "1. Scene " << opt.scene.string() << ": " << st.problem.numDofs() << " dofs, "
            << st.problem.contact.size() << " contact nodes, " << st.problem.numSteps()
            << " instants, kappa = " << st.scene.search_direction.scale << "\n";
  auto t0 = Clock::now();
  const stc::SolveResult ref = stc::solveIncremental(st.problem);
  st.incremental_s = secondsSince(t0);
  if (!ref.summary.converged()) throw std::runtime_error("incremental reference: " + ref.summary.message);
  const std::shared_ptr<const stc::SpdSolver> factor = stc::PreparedOperators().stiffnessFree(st.problem);
  const stc::SpdSolver& K = *factor;
  const stc::CondensedInterface condensed = stc::CondensedInterface::build(st.problem, K);
  st.reference = std::make_unique<stc::ErrorReference>(st.problem, K, condensed.delassus, ref.interface.lambda);
  t0 = Clock::now();
  st.modes = stc::fas::aposterioriModes(st.problem, K, ref.interface.lambda, kMaxModes);
  st.svd_s = secondsSince(t0);
  std::cout << "2. Reference (incremental) " << sci(st.incremental_s, 3) << " s; energy SVD, " << st.modes.cols()
            << " modes kept, " << sci(st.svd_s, 3) << " s (the a posteriori cost)\n";
  return st;
}

std::vector<Outcome> runAll(const Study& st, const Options& opt, stc::latin::GlobalStage& global) {
  std::cout << "3. Runs (cap " << opt.max_relaxations << " relaxations; stop at true error <= 1e-8)\n";
  std::vector<Outcome> all;
  for (const RunSpec& r : studyRuns(opt.small)) {
    const stc::SolveResult res = runOne(st, r, global, opt.max_relaxations);
    all.push_back({r, res.summary, statsOf(res.summary)});
    const Stats& s = all.back().stats;
    std::cout << "   " << std::left << std::setw(26) << r.name << std::right << " to 1e-4: " << std::setw(5)
              << count(s.to4, opt.max_relaxations) << "  to 1e-6: " << std::setw(5) << count(s.to6, opt.max_relaxations)
              << "  " << finalStatus(res.summary) << ", " << sci(res.summary.wall_s, 3) << " s\n";
    writeCsv(opt.out / (r.name + ".csv"), res.summary);
  }
  return all;
}

/// Step 7: FAS (10 SVD + 15 RES, ν = 2, start (a)) must reach true error 1e-4 before LATIN.
bool check(const std::vector<Outcome>& all) {
  const Stats* latin = nullptr;
  const Stats* fas = nullptr;
  for (const auto& o : all) {
    if (o.spec.name == "latin") latin = &o.stats;
    if (o.spec.name == "fas_m10_r15_nu2") fas = &o.stats;
  }
  const bool ok = latin && fas && fas->to4 && (!latin->to4 || *fas->to4 < *latin->to4);
  std::cout << "7. Check: FAS (10 SVD + 15 RES, nu = 2) reaches true error 1e-4 in fewer relaxations than LATIN: "
            << (ok ? "yes" : "NO") << "\n";
  return ok;
}

int run(const Options& opt) {
  const auto t0 = Clock::now();
  std::cout << "Options: scene " << opt.scene.string() << ", --out " << opt.out.string()
            << (opt.small ? ", --small" : "") << (opt.safeguard ? ", --safeguard" : "")
            << (opt.fixed_ic ? ", --fixed-ic" : "") << ", --max-relaxations " << opt.max_relaxations;
  for (const auto& s : opt.overrides) std::cout << ", --set " << s;
  std::cout << "\n";
  fs::create_directories(opt.out);
  const Study st = prepare(opt);
  stc::latin::GlobalStage global(st.problem);                // factorised once, shared by every run
  const std::vector<Outcome> all = runAll(st, opt, global);  // step 3
  const Cost cost = measureCost(st, global, opt.repeats);
  std::cout << "4. Fine relaxation " << sci(cost.relaxation_s * 1e3, 3) << " ms (local stage "
            << sci(cost.local_s * 1e3, 3) << " ms);";
  for (const auto& r : cost.rows)
    std::cout << " coarse step r = " << r.rank << ": " << sci(r.coarse_s * 1e3, 3) << " ms ("
              << sci(100 * r.coarse_ratio, 2) << "%), RES renewal " << sci(r.renew_s * 1e3, 3) << " ms;";
  std::cout << "\n";
  std::cout << "5. Figures\n";
  drawFigures(opt.out, figures(opt.small), all, opt.max_relaxations);
  writeSummary(opt.out / "summary.md", opt, st, cost, all, secondsSince(t0));
  std::cout << "6. " << (opt.out / "summary.md").string() << " and one CSV per run\n";
  const bool ok = check(all);
  std::cout << "Total " << sci(secondsSince(t0), 3) << " s\n";
  return ok ? 0 : 2;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The seed's Figs. 4-5: FAS with the a posteriori basis against LATIN (docs/fas_aposteriori.md)"};
  Options o;
  o.scene = fs::path(STC_SOURCE_DIR) / "examples/scenes/hemicylinder.toml";
  o.out = "results/fas_aposteriori";
  o.repeats = 31;
  stc::study::addStudyOptions(app, o);
  app.add_option("--max-relaxations", o.max_relaxations, "cap of fine relaxations per run")
      ->capture_default_str()
      ->check(CLI::Range(10, 1000000));
  auto* safeguard = app.add_flag("--safeguard", o.safeguard,
                                 "FAS with the coarse-step safeguard (the library's default); off: the seed's plain cycle");
  app.add_flag("--fixed-ic", o.fixed_ic, "with --safeguard: i_C fixed (adapted to the safeguard's verdicts by default)")
      ->needs(safeguard);
  return stc::study::runStudy(app, o, argc, argv, [&] { return run(o); });
}
