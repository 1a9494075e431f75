// stcontact compare SCENE: every strategy asked for (default: availableSolvers()) solves the
// scene `--repeats` times; the incremental reference, computed once, gives every iteration its true
// error. Writes, each atomically, into --out: work_precision.csv, summary.csv, summary.md and, through
// gnuplot, three PNG plots. docs/compare.md describes every file and how time and memory are measured.
#include "src/cli/compare_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <sstream>

#include "src/cli/commands.hpp"
#include "src/cli/compare_plots.hpp"
#include "src/cli/compare_runs.hpp"
#include "src/core/input_error.hpp"
#include "src/io/atomic_file.hpp"
#include "src/report/comparison_writer.hpp"
#include "src/report/number_format.hpp"
#include "src/scene/scene_reader.hpp"
#include "src/strategies/solve_by_name.hpp"
#include "stc_git_commit.hpp"  // STC_GIT_COMMIT, generated at build time

namespace stc::cli {
namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::string commandLine(const CompareArgs& a, const std::vector<std::string>& solvers,
                        const std::filesystem::path& out) {
  std::string joined;
  for (const auto& s : solvers) joined += (joined.empty() ? "" : ",") + s;
  std::string line = "stcontact compare " + a.scene + " --solvers " + joined + " --out " + out.string() +
                     " --repeats " + std::to_string(a.repeats);
  for (const auto& o : a.overrides) line += " --set " + o;
  if (a.tolerance) line += " --tol " + shortNumber(*a.tolerance, 6);
  return line;
}

void printStrategy(const StrategyMeasurement& m) {
  const StrategySummary s = summarize(m);
  std::cout << "  " << m.solver << ": " << toString(m.termination) << ", median " << shortNumber(s.median_total_s, 3)
            << " s";
  for (const Reach& r : s.reaches)
    std::cout << ", " << targetLabel(r.target) << " " << (r.wall_s ? shortNumber(*r.wall_s, 3) + " s" : "not reached");
  std::cout << std::endl;
}

}  // namespace

// Split here rather than by CLI11's ->delimiter(','): CLI11 2.1.2 (Debian 12) drops empty items, so
// "--solvers latin,,incremental" would pass as two names instead of the documented refusal
// "--solvers: empty name" (docs/compare.md; the ctest case cli.compare_empty_solver_name).
std::vector<std::string> solverList(const std::string& list) {
  if (trimmed(list).empty()) return availableSolvers();
  std::vector<std::string> names;
  std::stringstream items(list);
  std::string item;
  while (std::getline(items, item, ',')) {
    const std::string name = trimmed(item);
    if (name.empty()) throw InputError("--solvers: empty name in '" + list + "'");
    requireAvailable(name);
    if (std::find(names.begin(), names.end(), name) != names.end())
      throw InputError("--solvers: '" + name + "' is listed twice");
    names.push_back(name);
  }
  return names;
}

Comparison describeComparison(const std::string& scene_file, const std::string& command, const Scene& scene,
                              const Problem& problem, int repeats) {
  Comparison c;
  c.scene_name = scene.name;
  c.scene_file = scene_file;
  c.command = command;
  c.n_dofs = problem.numDofs();
  c.n_contact_nodes = problem.contact.size();
  c.n_steps = problem.numSteps();
  c.tolerance = scene.solver.tolerance;
  c.repeats = repeats;
  c.environment = describeRunEnvironment(STC_BUILD_TYPE, STC_GIT_COMMIT);
  return c;
}

CLI::App* addCompareCommand(CLI::App& app, CompareArgs& args) {
  auto* cmd = app.add_subcommand("compare", "work-precision comparison of strategies (docs/compare.md)");
  cmd->add_option("scene", args.scene, "scene file (TOML)")->required();
  cmd->add_option("--solvers", args.solvers, "comma-separated strategies (default: every available one)");
  cmd->add_option("--out", args.out, "report folder (default results/<scene name>/compare)");
  cmd->add_option("--repeats", args.repeats, "timed runs per strategy, medians over them")->capture_default_str();
  cmd->add_option("--set", args.overrides, "override a scene value: section.key=value")->take_all();
  cmd->add_option("--tol", args.tolerance, "tolerance on the error estimate (default: the scene's)");
  cmd->add_flag("--quiet", args.quiet, "no progress, no final report");
  return cmd;
}

int runCompare(const CompareArgs& args) {
  if (args.repeats < 1) throw InputError("--repeats must be >= 1");
  Scene scene = loadScene(args.scene, args.overrides);
  const std::vector<std::string> solvers = solverList(args.solvers);
  if (args.tolerance) {
    if (!(*args.tolerance > 0.0)) throw InputError("--tol must be > 0");
    scene.solver.tolerance = *args.tolerance;
  }
  const std::filesystem::path out =
      args.out ? std::filesystem::path(*args.out) : std::filesystem::path("results") / scene.name / "compare";
  ensureWritableDirectory(out);  // fail before the runs, not after
  const Problem problem = buildProblem(scene);
  Comparison comparison = describeComparison(args.scene, commandLine(args, solvers, out), scene, problem, args.repeats);

  const ReferenceSolution reference = computeReference(problem, args.quiet);
  comparison.reference_s = reference.total_s;
  const CompareContext context{problem, scene.solver, reference, args.repeats, args.quiet};
  for (const std::string& solver : solvers) {
    comparison.strategies.push_back(measureStrategy(solver, context));
    if (!args.quiet) printStrategy(comparison.strategies.back());
  }
  comparison.memory_method = describeMemoryMethod(comparison.strategies.front().memory.since_reset);
  comparison.load_after = loadAverage();
  writeComparison(out, comparison);

  std::string warning;
  if (!drawWorkPrecisionPlots(out, comparison, warning)) std::cerr << "warning: " << warning << std::endl;
  if (!args.quiet) std::cout << "report: " << (out / "summary.md").string() << std::endl;
  return 0;
}

}  // namespace stc::cli
