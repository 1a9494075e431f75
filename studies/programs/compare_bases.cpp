// Description
//   A posteriori vs a priori coarse bases (docs/method.md §4–5; report: docs/compare_bases.md). On one scene,
//   runs `latin`, `latin-pgd`, `fas-aposteriori`, `fas-apriori` with the true error of every
//   relaxation, and `incremental` as the reference point; times each strategy (median of --repeats
//   runs without the error evaluation); counts the a posteriori SVD (and the solve it needs) apart;
//   then checks the a priori basis against the SVD of the converged solution (principal angles,
//   projection errors; the SVD is used here only, never on a solve path).
// Sample run
//   build/bin/compare_bases examples/scenes/hemicylinder.toml --out results/compare_bases
//   build/bin/compare_bases examples/scenes/hemicylinder.toml --small --out /tmp/cb   (ctest case)
//   build/bin/compare_bases --help
//   Then the like-for-like runs (studies/programs/like_for_like.hpp): both bases on the same fine level
//   with coarse spaces of equal size, the seed paper's full-order FAS, fas-apriori with one ingredient
//   off at a time and the incremental solver, each a solve at --tol stopping on its estimate.
// Options: SCENE, --out DIR, --set KEY=VALUE (repeatable), --small (mesh.arc_nodes=21,
//   time.steps=21), --repeats N (timed runs per strategy, default 5), --no-verify (skip the SVD
//   verification of the a priori basis), --tol τ (the like-for-like solves' tolerance, default 1e-6),
//   --like-for-like-only (those solves alone: for meshes where latin to 1e-8 takes minutes).
// Output in DIR: <strategy>.csv (relaxation,sparse_solves,indicator,error,wall_s,rank),
//   summary.md (tables), compare_bases.gp and compare_bases.png (error against relaxations and
//   against wall time).
// Exit status: 0 ok, 1 bad input, 2 the check failed (fas-apriori must converge, agree with
//   incremental to 1e-5 in energy, and reach 1e-4 in fewer relaxations than latin; every
//   like-for-like solve must converge with a true error within --tol), 3 internal.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/fas/aposteriori/aposteriori_basis.hpp"
#include "stcontact/fas/apriori/apriori_basis.hpp"
#include "stcontact/fas/fas_solver.hpp"
#include "stcontact/incremental/condensed_interface.hpp"
#include "stcontact/incremental/error_reference.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/operators/displacement.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/pgd/basis_verification.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/strategies/registry.hpp"
#include "stcontact/studies/gnuplot_runner.hpp"
#include "stcontact/studies/programs/like_for_like.hpp"
#include "stcontact/studies/programs/study_program.hpp"
#include "stcontact/studies/work_precision.hpp"

namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kStrategies = {"latin", "latin-pgd", "fas-aposteriori", "fas-apriori"};
const std::vector<double> kTargets = {1e-2, 1e-4, 1e-6};

struct Options : stc::study::StudyOptions {
  bool verify = true;  ///< off with --no-verify (parameter scans)
  double tau = 1e-6;   ///< --tol: the tolerance of the like-for-like solves
  bool like_only = false;  ///< --like-for-like-only: those solves alone (no latin, no figure)
};

struct Setup {
  stc::Scene scene;
  stc::Problem problem;
  stc::SolveResult incremental;
  double incremental_s = 0.0;
  std::shared_ptr<const stc::SpdSolver> K;  ///< K_ff, prepared once for the measure and the SVD
  std::unique_ptr<stc::ErrorReference> reference;
};

struct Run {
  std::string name;
  stc::SolveSummary summary;  ///< the run with the true error
  double median_s = 0.0;      ///< median wall time of the timed runs (no error evaluation)
};

Run runStrategy(const Setup& st, const std::string& name, int repeats) {
  stc::SolveInputs with_error;
  with_error.reference = st.reference.get();
  with_error.converged_lambda = &st.incremental.interface.lambda;
  with_error.spatial_modes = false;
  Run run{name, stc::solve(stc::strategyNamed(name), st.problem, st.scene.solver, with_error).summary, 0.0};
  stc::SolveInputs timed;
  timed.converged_lambda = &st.incremental.interface.lambda;
  timed.spatial_modes = false;  // the verification below solves once more for them
  std::vector<double> times;
  for (int i = 0; i < repeats; ++i)
    times.push_back(stc::solve(stc::strategyNamed(name), st.problem, st.scene.solver, timed).summary.wall_s);
  run.median_s = stc::median(times);
  return run;
}

// The first record at or below `target`, its wall time rescaled to the timed runs (the error run's
// clock includes one true-error evaluation per record).
const stc::IterationRecord* firstBelow(const Run& r, double target) {
  return stc::study::firstRecordBelow(r.summary, target);
}
double timedWall(const Run& r, const stc::IterationRecord& h) {
  return r.summary.wall_s > 0 ? h.wall_s * r.median_s / r.summary.wall_s : h.wall_s;
}

void writeCsv(const fs::path& file, const Run& r) {
  std::ofstream out(file);
  out << "relaxation,sparse_solves,indicator,error,wall_s,rank\n" << std::setprecision(6);
  for (const auto& h : r.summary.history)
    out << h.relaxations << ',' << h.sparse_solves << ',' << h.indicator << ',' << h.error.value_or(NAN) << ','
        << timedWall(r, h) << ',' << h.rank << '\n';
}

struct Verification {
  std::vector<int> sizes;
  std::vector<double> min_cosine, apriori_error, svd_error;
  int apriori_rank = 0;
  double full_apriori_error = 0.0;
};

// The a priori basis of one fas-apriori solve against the energy-SVD modes of the converged
// solution, in the K_ff energy product.
Verification verify(const Setup& st) {
  // The energy modes of the a priori expansion at the end of the solve (pgd/separated_history.hpp):
  // what the coarse space takes its leading modes from.
  const Eigen::MatrixXd apriori = stc::solve(stc::strategyNamed("fas-apriori"), st.problem, st.scene.solver).spatial_modes;
  const Eigen::MatrixXd U = stc::freeDisplacements(st.problem, *st.K, st.incremental.interface.lambda);
  const Eigen::MatrixXd svd = stc::fas::aposterioriModes(st.problem, *st.K, st.incremental.interface.lambda, 20);
  const auto& M = st.problem.stiffness_free;
  Verification v;
  v.apriori_rank = static_cast<int>(apriori.cols());
  v.full_apriori_error = stc::pgd::projectionError(U, apriori, M);
  for (int k : {2, 5, 10, 20}) {
    if (k > svd.cols() || k > apriori.cols()) break;
    v.sizes.push_back(k);
    const Eigen::VectorXd c = stc::pgd::principalCosines(svd.leftCols(k), apriori, M);
    v.min_cosine.push_back(c.size() ? c.minCoeff() : 0.0);
    v.apriori_error.push_back(stc::pgd::projectionError(U, apriori.leftCols(k), M));
    v.svd_error.push_back(stc::pgd::projectionError(U, svd.leftCols(k), M));
  }
  return v;
}

std::string cell(const Run& r, double target) {
  const auto* h = firstBelow(r, target);
  if (!h) return "·";
  std::ostringstream s;
  s << h->relaxations << " / " << h->sparse_solves << " / " << std::setprecision(3) << timedWall(r, *h);
  return s.str();
}

// The like-for-like section (studies/programs/like_for_like.hpp).
void writeLikeForLike(std::ostream& md, const std::vector<stc::study::VariantRun>& runs, const Options& o) {
  md << "\n## Like for like: the same fine level, coarse spaces of equal size\n\n"
     << "Each row is a solve at τ = " << o.tau << " that stops on its own estimate (the true error at termination"
     << " beside it), timed alternated with the others, median of " << o.repeats << " rounds. The a posteriori"
     << " basis takes as many SVD modes and residual vectors as the a priori one takes energy modes and modes of"
     << " the change; its SVD (and the solve it needs) are not in its time.\n\n";
  stc::study::writeVariantTable(md, runs);
}

void writeSummary(const fs::path& file, const Setup& st, const std::vector<Run>& runs, double svd_s,
                  const Verification& v, const Options& o, const std::vector<stc::study::VariantRun>& like) {
  std::ofstream md(file);
  const auto& p = st.problem;
  md << "# A posteriori vs a priori bases: " << p.name << "\n\n"
     << p.numDofs() << " dofs, " << p.contact.size() << " contact nodes, " << p.numSteps()
     << " instants, κ = " << st.scene.search_direction.scale << ", tolerance " << st.scene.solver.tolerance()
     << ", ν1 = ν2 = " << st.scene.solver.fas_aposteriori.fas.pre_relaxations
     << ", i_C = "
     << st.scene.solver.fas_aposteriori.fas.coarseIterationsIn(p.dimension)
     << ", N_res = " << st.scene.solver.fas_aposteriori.basis.residual_vectors << ". Wall times: median of " << o.repeats
     << " runs without the true-error evaluation.\n\n"
     << "| strategy | status | relaxations | sparse solves | rank | final error | wall (s) |";
  for (double t : kTargets) md << " to " << t << ": relax / solves / s |";
  md << "\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  md << "| incremental | converged | · | · | · | 0 (reference) | " << std::setprecision(3) << st.incremental_s
     << " | · | · | · |\n";
  for (const auto& r : runs) {
    const auto& last = r.summary.history.back();
    md << "| " << r.name << " | " << toString(r.summary.termination) << " | " << r.summary.relaxations << " | "
       << last.sparse_solves << " | " << last.rank << " | " << std::setprecision(2) << r.summary.error.value_or(NAN)
       << " | " << std::setprecision(3) << r.median_s << " |";
    for (double t : kTargets) md << ' ' << cell(r, t) << " |";
    md << '\n';
  }
  md << "\nThe a posteriori SVD (energy SVD of the incremental solution, 20 modes) took " << std::setprecision(3)
     << svd_s << " s, plus the incremental solve it needs (" << st.incremental_s
     << " s); neither is in fas-aposteriori's wall time above.\n\n";
  md << "## Ratios to LATIN (relaxations, wall time) to reach the true error\n\n| strategy |";
  for (double t : kTargets) md << ' ' << t << " |";
  md << "\n|---|---:|---:|---:|\n";
  for (const auto& r : runs) {
    md << "| " << r.name << " |";
    for (double t : kTargets) {
      const auto *h = firstBelow(r, t), *l = firstBelow(runs.front(), t);
      if (!h || !l) md << " · |";
      else md << ' ' << std::setprecision(2) << double(h->relaxations) / l->relaxations << ", "
              << timedWall(r, *h) / timedWall(runs.front(), *l) << " |";
    }
    md << '\n';
  }
  md << "\n## The a priori basis against the SVD of the converged solution (K_ff energy)\n\n"
     << "The fas-apriori expansion has " << v.apriori_rank << " energy modes at the end of the solve; "
     << "projection error of the converged history on all of them: " << std::setprecision(2)
     << v.full_apriori_error << ".\n\n| k | smallest cosine, SVD_k vs a priori basis | projection error on a priori modes 1..k"
     << " | on SVD modes 1..k |\n|---:|---:|---:|---:|\n";
  for (std::size_t i = 0; i < v.sizes.size(); ++i)
    md << "| " << v.sizes[i] << " | " << std::setprecision(4) << v.min_cosine[i] << " | " << std::setprecision(2)
       << v.apriori_error[i] << " | " << v.svd_error[i] << " |\n";
  writeLikeForLike(md, like, o);
  md << "\n![error against relaxations and wall time](compare_bases.png)\n";
}

// Error against relaxations and against wall time, one colour per strategy (the line of
// scripts/plots/work_precision.gp), the incremental solver's time marked, and fas-aposteriori again
// with the cost of what it needs first (the incremental solve and the SVD) added to its times.
void plot(const fs::path& dir, const std::string& scene, double incremental_s, double svd_s) {
  std::ofstream gp(dir / "compare_bases.gp");
  const double before_s = incremental_s + svd_s;
  gp << "if (!exists('suffix')) suffix = ''\n"
     << "colour(s) = s eq 'latin' ? '#1f77b4' : s eq 'latin-pgd' ? '#ff7f0e' : s eq 'fas-aposteriori' ? '#2ca02c' : "
        "s eq 'fas-apriori' ? '#d62728' : s eq 'incremental' ? '#202020' : '#9467bd'\n"
     << "set terminal pngcairo size 1200,520 font ',10' noenhanced\nset output 'compare_bases.png'.suffix\n"
     << "set datafile separator ','\nset logscale y\nset format y '1e%T'\nset key top right\nset grid\n"
     << "set multiplot layout 1,2 title '" << scene
     << ": a posteriori (SVD of the converged solution) against a priori (built during the iterations) bases'\n"
     << "set title 'true error against fine relaxations'\nset xlabel 'fine relaxations'\n"
     << "set ylabel 'true error (relative energy)'\nfiles = '";
  for (const auto& s : kStrategies) gp << s << ' ';
  gp << "'\nplot for [f in files] f.'.csv' using 1:4 with linespoints pt 7 ps 0.4 lw 2 lc rgb colour(f) title f\n"
     << "set title 'true error against wall time (dashed: + the solve and SVD it needs, " << std::setprecision(3)
     << before_s << " s)'\nset xlabel 'wall time (s)'\nset logscale x\n"
     << "set arrow 1 from " << incremental_s << ", graph 0 to " << incremental_s
     << ", graph 1 nohead dt 2 lw 2 lc rgb colour('incremental')\n"
     << "set label 1 'incremental (exact): " << incremental_s << " s' at " << incremental_s
     << ", graph 0.03 rotate by 90 left offset -0.8,0\n"
     << "plot for [f in files] f.'.csv' using 5:4 with linespoints pt 7 ps 0.4 lw 2 lc rgb colour(f) title f, \\\n"
     << "     'fas-aposteriori.csv' using ($5 + " << before_s
     << "):4 with lines dt 2 lw 2 lc rgb colour('fas-aposteriori') title 'fas-aposteriori + SVD'\n"
     << "unset multiplot\n";
  gp.close();
  const stc::PlotJob job{"compare_bases.gp", "", {"compare_bases.png"}, false};
  if (stc::runPlots(dir, job).status != stc::PlotStatus::Drawn)
    std::cerr << "warning: no figure (gnuplot missing or failed); draw it later with: cd '" << dir.string()
              << "' && " << stc::plotCommand(job) << "\n";
}

Setup setUp(const Options& o) {
  Setup st;
  st.scene = stc::readScene(o.scene, o.overrides);
  st.problem = stc::buildProblem(st.scene);
  std::vector<double> times;
  for (int i = 0; i < o.repeats; ++i) times.push_back(stc::study::secondsOf([&] { st.incremental = stc::solveIncremental(st.problem); }));
  st.incremental_s = stc::median(times);
  st.K = stc::PreparedOperators().stiffnessFree(st.problem);
  const auto condensed = stc::CondensedInterface::build(st.problem, *st.K);
  st.reference = std::make_unique<stc::ErrorReference>(st.problem, *st.K, condensed.delassus,
                                                       st.incremental.interface.lambda);
  return st;
}

bool check(const std::vector<Run>& runs) {
  const Run& latin = runs.front();
  const Run& apriori = runs.back();
  const auto *a = firstBelow(apriori, 1e-4), *l = firstBelow(latin, 1e-4);
  return apriori.summary.converged() && apriori.summary.error && *apriori.summary.error <= 1e-5 && a && l &&
         a->relaxations < l->relaxations;
}

// The like-for-like runs (studies/programs/like_for_like.hpp), printed as they end.
std::vector<stc::study::VariantRun> likeForLike(const Setup& st, const Options& o) {
  stc::SolveInputs with_error, timed;
  with_error.reference = st.reference.get();
  with_error.converged_lambda = timed.converged_lambda = &st.incremental.interface.lambda;
  with_error.spatial_modes = timed.spatial_modes = false;
  auto runs = stc::study::runAlternated(st.problem, stc::study::likeForLikeVariants(st.scene.solver, o.tau),
                                        with_error, timed, o.repeats);
  for (const auto& r : runs)
    std::cout << r.variant.label << ": " << toString(r.summary.termination) << ", " << r.summary.relaxations
              << " relaxations, true error " << r.summary.error.value_or(NAN) << ", median " << r.median_s << " s\n";
  return runs;
}

// Every like-for-like solve converged with a true error within τ (the incremental row is the reference).
bool likeForLikeHolds(const std::vector<stc::study::VariantRun>& like, double tau) {
  return std::all_of(like.begin(), like.end(), [&](const stc::study::VariantRun& r) {
    return r.variant.strategy == stc::Strategy::Incremental ||
           (r.summary.converged() && r.summary.error && *r.summary.error <= tau);
  });
}

int study(const Options& o) {
  const Setup st = setUp(o);
  fs::create_directories(o.out);
  std::vector<Run> runs;
  if (!o.like_only)
    for (const auto& name : kStrategies) {
      runs.push_back(runStrategy(st, name, o.repeats));
      writeCsv(o.out / (name + ".csv"), runs.back());
      std::cout << name << ": " << toString(runs.back().summary.termination) << ", "
                << runs.back().summary.relaxations << " relaxations, error "
                << runs.back().summary.error.value_or(NAN) << ", median " << runs.back().median_s << " s\n";
    }
  const auto like = likeForLike(st, o);
  if (o.like_only) {
    std::ofstream md(o.out / "summary.md");
    md << "# Like for like: " << st.problem.name << "\n\n" << st.problem.numDofs() << " dofs, "
       << st.problem.contact.size() << " contact nodes, " << st.problem.numSteps() << " instants.\n";
    writeLikeForLike(md, like, o);
  } else {
    std::vector<double> svd_times;
    for (int i = 0; i < o.repeats; ++i)
      svd_times.push_back(stc::study::secondsOf(
          [&] { stc::fas::aposterioriModes(st.problem, *st.K, st.incremental.interface.lambda, 20); }));
    const Verification v = o.verify ? verify(st) : Verification{};
    writeSummary(o.out / "summary.md", st, runs, stc::median(svd_times), v, o, like);
    plot(o.out, st.problem.name, st.incremental_s, stc::median(svd_times));
  }
  std::cout << "report: " << (o.out / "summary.md").string() << "\n";
  if (!o.like_only && !check(runs)) {
    std::cerr << "check failed: fas-apriori must converge, agree with incremental to 1e-5 and beat latin to 1e-4\n";
    return 2;
  }
  if (!likeForLikeHolds(like, o.tau)) {
    std::cerr << "check failed: every like-for-like solve must converge with a true error within --tol\n";
    return 2;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"A posteriori vs a priori coarse bases (docs/compare_bases.md)"};
  Options o;
  o.scene = "examples/scenes/hemicylinder.toml";
  o.out = "results/compare_bases";
  o.repeats = 5;
  stc::study::addStudyOptions(app, o);
  bool no_verify = false;
  app.add_flag("--no-verify", no_verify, "skip the SVD verification of the a priori basis");
  app.add_option("--tol", o.tau, "tolerance of the like-for-like solves (each stops on its own estimate)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_flag("--like-for-like-only", o.like_only, "the like-for-like solves alone (no latin, no SVD check)");
  return stc::study::runStudy(app, o, argc, argv, [&] {
    o.verify = !no_verify;
    return study(o);
  });
}
