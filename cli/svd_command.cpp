// stcontact svd SCENE: the a posteriori space-time analysis of docs/method.md §3 and the seed paper's §3
// (Figs. 2 and 3). Solves the scene with the incremental solver (exact to round-off), builds the
// full displacement history U (n × m), computes its SVD in the energy product with ARPACK
// (U = Σ σ_i Υ_i ν_iᵀ, Υᵀ K Υ = I; pgd/space_time_svd.hpp), checks it against the dense eigensolver
// when m is small, measures each mode's localisation at the contact zone (studies/mode_localisation.hpp)
// and writes every file atomically into --out (default results/<scene>/svd):
//   singular_values.csv, time_functions.csv, localisation.csv, modes.vtu, modes_deformed.dat,
//   svd_figures.gp, svd_summary.json and, through gnuplot, singular_values.png, time_functions.png,
//   modes.png. Verification only: nothing here is on a solve path.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include "stcontact/cli/commands.hpp"
#include "stcontact/core/clock.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/core/interruption.hpp"
#include "stcontact/io/atomic_file.hpp"
#include "stcontact/io/json_writer.hpp"
#include "stcontact/io/run_folder.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/studies/mode_localisation.hpp"
#include "stcontact/studies/solution_svd.hpp"
#include "stcontact/studies/svd_figures.hpp"
#include "stcontact/studies/svd_tables.hpp"

namespace stc::cli {
namespace {

constexpr int kFigureModes = 6;            // seed Figs. 2 and 3b show 6
constexpr int kComparedValues = 10;        // the check of docs/svd_seed.md: the leading 10 σ, ARPACK vs dense
constexpr int kMaxDenseCheck = 2000;       // m above which the O(m³) dense check is skipped
constexpr double kEnergyLevels[] = {0.99, 0.999, 0.9999};
constexpr const char* kEnergyLabels[] = {"99%", "99.9%", "99.99%"};
// Bands around the contact zone, in units of the scene's length scale (the radius for the seed):
// 1.5, 3 and 6 element sizes at the seed's arc (studies/mode_localisation.hpp explains the choice).
constexpr double kBandDepths[] = {0.05, 0.1, 0.2};
constexpr double kFigureDisplacement = 0.12;  // largest displacement of a drawn mode, × length scale

struct Analysis {
  pgd::SpaceTimeSvd svd;
  double svd_s = 0.0;
  std::optional<double> dense_difference;  ///< max relative |σ_ARPACK − σ_dense| on the leading values
  int compared = 0;
  /// Modes for each energy level of the Euclidean SVD of U (rigid motion included), for comparison
  /// with the seed, whose "SVD" does not say which product it used.
  std::vector<std::optional<int>> euclidean_modes;
};

Analysis analyse(const Eigen::MatrixXd& U, const Eigen::SparseMatrix<double>& K, int wanted) {
  const int m = static_cast<int>(U.cols());
  Analysis a;
  const auto start = std::chrono::steady_clock::now();
  a.svd = arpackEnergySvd(U, K, wanted);
  a.svd_s = secondsSince(start);
  if (m <= kMaxDenseCheck) {
    const pgd::SpaceTimeSvd dense = pgd::energySvd(U, K);
    a.compared = std::min({kComparedValues, a.svd.size(), a.svd.resolved});
    double worst = 0.0;
    for (int i = 0; i < a.compared; ++i)
      worst = std::max(worst, std::abs(a.svd.sigma[i] - dense.sigma[i]) / dense.sigma[i]);
    a.dense_difference = worst;
    const pgd::SpaceTimeSvd plain = pgd::plainSvd(U);
    for (double level : kEnergyLevels) a.euclidean_modes.push_back(plain.modesFor(level));
  }
  return a;
}

std::string summaryJson(const Problem& problem, const Analysis& a, const ModeLocalisation* loc,
                        double solve_s) {
  JsonObject levels;
  for (int j = 0; j < 3; ++j) levels.add(kEnergyLabels[j], a.svd.modesFor(kEnergyLevels[j]));
  JsonObject json;
  json.add("scene", problem.name)
      .add("n_dofs", problem.numDofs())
      .add("n_steps", problem.numSteps())
      .add("solver", "incremental")
      .add("solve_s", solve_s)
      .add("method", "arpack (dsaupd/dseupd, LA, tol = machine precision)")
      .add("pairs_computed", a.svd.size())
      .add("pairs_resolved", a.svd.resolved)
      .add("operator_applications", a.svd.operator_applications)
      .add("svd_s", a.svd_s)
      .add("total_energy", a.svd.total_energy)
      .add("modes_for_energy", std::move(levels))
      .add("dense_check_values", a.compared)
      .add("dense_check_max_relative_difference", a.dense_difference);
  if (!a.euclidean_modes.empty()) {
    JsonObject euclidean;
    for (int j = 0; j < 3; ++j) euclidean.add(kEnergyLabels[j], a.euclidean_modes[j]);
    json.add("euclidean_modes_for_norm", std::move(euclidean));
  }
  if (loc) {
    JsonObject zone;
    zone.add("nodes", static_cast<int>(loc->zone().nodes.size()))
        .add("xmin", loc->zone().xmin)
        .add("xmax", loc->zone().xmax)
        .add("band_depths", loc->bandDepths())
        .add("band_area_shares", loc->bandAreaShares());
    json.add("contact_zone", std::move(zone));
  }
  return json.str() + "\n";
}

// Figures: data, script, then gnuplot; a missing or failing gnuplot is reported, not fatal.
void writeFigures(const RunFolder& folder, const Problem& problem, const Analysis& a,
                  const ModeLocalisation* loc) {
  const std::filesystem::path& out = folder.path();
  const int drawn = std::min({kFigureModes, a.svd.size()});
  SvdFigureSpec spec;
  spec.scene = problem.name;
  spec.singular_values = std::min(kSvdFigurePairs, a.svd.size());
  spec.time_functions = drawn;
  writeFileAtomically(out / "modes_deformed.dat",
                      deformedModesData(std::get<TriMesh>(problem.body), a.svd, drawn, loc,
                                             kFigureDisplacement * problem.length_scale, spec.mode_scales));
  for (int i = 0; i < drawn; ++i) spec.mode_energy.push_back(a.svd.energyFraction(i));
  writeFileAtomically(out / "svd_figures.gp", svdFiguresScript(spec));
  std::string detail;
  const FigureStatus status = drawSvdFigures(out, detail);
  if (status == FigureStatus::GnuplotMissing) std::cerr << "note: " << folder.named(detail) << "\n";
  if (status == FigureStatus::GnuplotFailed) std::cerr << "warning: " << folder.named(detail) << "\n";
}

// The contact zone's localisation bands, or none (with a note) when no node ever closes.
std::unique_ptr<ModeLocalisation> localisation(const Problem& problem, const SolveResult& solved) {
  ContactZone zone = ContactZone::everClosed(problem, solved);
  if (zone.empty()) {
    std::cerr << "note: no contact node ever closes: no contact zone, no localisation.csv\n";
    return nullptr;
  }
  std::vector<double> depths;
  for (double d : kBandDepths) depths.push_back(d * problem.length_scale);
  return std::make_unique<ModeLocalisation>(problem, std::move(zone), depths);
}

void report(const std::filesystem::path& out, const Problem& problem, const Analysis& a,
            const ModeLocalisation* loc, int modes) {
  std::printf("svd: %s, %d dofs x %d instants, energy SVD by ARPACK: %d pairs (%d resolved), %d products, %.3g s\n",
              problem.name.c_str(), problem.numDofs(), problem.numSteps(), a.svd.size(), a.svd.resolved,
              a.svd.operator_applications, a.svd_s);
  if (!(a.svd.total_energy > 0.0)) {
    std::printf("  the history carries no elastic energy (rigid motion only): nothing to decompose\n");
    std::printf("  results in %s/\n", out.string().c_str());
    return;
  }
  for (double level : kEnergyLevels) {
    const auto count = a.svd.modesFor(level);
    if (count) std::printf("  modes for %g%% of the elastic energy: %d\n", 100.0 * level, *count);
    else std::printf("  modes for %g%% of the elastic energy: more than %d\n", 100.0 * level, a.svd.size());
  }
  if (a.dense_difference)
    std::printf("  ARPACK vs dense eigensolver, leading %d sigma: max relative difference %.2e\n", a.compared,
                *a.dense_difference);
  if (!a.euclidean_modes.empty()) {
    std::printf("  for comparison, Euclidean SVD of U (rigid motion included), modes for 99/99.9/99.99%% of ||U||^2:");
    for (const auto& count : a.euclidean_modes) std::printf(count ? " %d" : " >%d", count ? *count : a.svd.size());
    std::printf("\n");
  }
  if (loc) {
    std::printf("  contact zone: %zu nodes, x in [%.3f, %.3f]; energy share within %g of it (area share %.3f):\n",
                loc->zone().nodes.size(), loc->zone().xmin, loc->zone().xmax, loc->bandDepths()[1],
                loc->bandAreaShares()[1]);
    std::printf("   ");
    for (int i = 0; i < std::min(modes, a.svd.resolved); ++i)
      std::printf(" %d: %.2f", i + 1, loc->measure(a.svd.space.col(i)).band_share[1]);
    std::printf("\n");
  }
  std::printf("  results in %s/\n", out.string().c_str());
}

}  // namespace

CLI::App* addSvdCommand(CLI::App& app, SvdArgs& args) {
  auto* cmd = app.add_subcommand("svd", "space-time SVD of the solution in the energy product (verification)");
  cmd->add_option("scene", args.scene, "scene file (TOML)")->required();
  cmd->add_option("--set", args.overrides, "override a scene value: section.key=value")->take_all();
  cmd->add_option("--out", args.out, "output folder (default results/<scene name>/svd)");
  cmd->add_option("--modes", args.modes, "pairs written to time_functions.csv, modes.vtu, localisation.csv")
      ->capture_default_str();
  cmd->add_option("--solver", args.solver, "solver of the analysed solution (incremental only)")
      ->capture_default_str();
  return cmd;
}

int runSvd(const SvdArgs& args) {
  const Scene scene = readScene(args.scene, args.overrides);
  if (args.solver != "incremental")
    throw InputError("svd analyses the incremental solution: --solver must be 'incremental', not '" + args.solver +
                     "'");
  const std::filesystem::path out =
      args.out ? std::filesystem::path(*args.out) : std::filesystem::path("results") / scene.name / "svd";
  const Problem problem = buildProblem(scene);
  checkSvdSizes(problem.numSteps(), args.modes);
  RunFolder folder(out);  // every input checked (--modes 0 created the folder): locked, written whole at the end
  const std::filesystem::path& dir = folder.path();

  const SolutionHistory history = incrementalHistory(problem);
  const SolveResult& solved = history.solved;
  const double solve_s = history.solve_s;
  if (!solved.summary.converged()) {
    std::cerr << "error: the incremental solver did not converge (" << solved.summary.message
              << "): no SVD written\n";
    return 2;
  }
  const Analysis a = analyse(history.U, problem.stiffness, args.modes);
  const int modes = std::min(args.modes, a.svd.size());

  // The localisation bands, the mode figures and modes.vtu draw plane meshes: 2D scenes only.
  const bool plane = problem.dimension == 2;
  if (!plane) std::cerr << "note: 3D scene: tables and svd_summary.json only (mode figures, localisation and modes.vtu are 2D)\n";
  const std::unique_ptr<ModeLocalisation> loc = plane ? localisation(problem, solved) : nullptr;

  throwIfInterrupted();
  writeFileAtomically(dir / "singular_values.csv", singularValuesCsv(a.svd));
  writeFileAtomically(dir / "time_functions.csv", timeFunctionsCsv(a.svd, problem.times, modes));
  if (loc) writeFileAtomically(dir / "localisation.csv", localisationCsv(a.svd, *loc, modes));
  if (plane) writeFileAtomically(dir / "modes.vtu", modesVtu(std::get<TriMesh>(problem.body), a.svd, modes, loc.get()));
  writeFileAtomically(dir / "svd_summary.json", summaryJson(problem, a, loc.get(), solve_s));
  if (plane && a.svd.total_energy > 0.0) writeFigures(folder, problem, a, loc.get());
  else if (plane) std::cerr << "note: zero elastic energy over the history: no figures\n";
  folder.commit();
  report(out, problem, a, loc.get(), modes);
  return 0;
}

}  // namespace stc::cli
