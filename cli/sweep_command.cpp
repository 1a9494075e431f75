// stcontact sweep SCENE --set-range KEY=FROM:TO:COUNT: every value's scene and problem are checked
// first (a bad range, an unknown key or a value out of range is refused before anything is written),
// then each value is solved warm (from the previous value's solution) and cold; sweep.csv, summary.md
// and, through gnuplot, sweep.png go into --out. docs/sweep.md describes every file.
#include "stcontact/cli/stopping_help.hpp"
#include "stcontact/cli/sweep_command.hpp"

#include <CLI/CLI.hpp>
#include <iostream>

#include "stcontact/cli/commands.hpp"
#include "stcontact/cli/terminal_progress.hpp"
#include "stcontact/cli/threads_option.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/core/interruption.hpp"
#include "stcontact/io/run_folder.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/strategies/registry.hpp"
#include "stcontact/studies/gnuplot_runner.hpp"
#include "stcontact/studies/number_format.hpp"
#include "stcontact/studies/solve_options.hpp"
#include "stcontact/studies/sweep_runs.hpp"
#include "stcontact/studies/sweep_writer.hpp"

namespace stc::cli {
namespace {

namespace fs = std::filesystem;

std::string keyOf(const std::string& override_text) {
  const std::string key = override_text.substr(0, override_text.find('='));
  const auto first = key.find_first_not_of(" \t");
  return first == std::string::npos ? "" : key.substr(first, key.find_last_not_of(" \t") - first + 1);
}

/// The scene of every value, each read with the --set overrides and then the value's own; the
/// scene reader refuses an unknown key or a value out of its range. Each problem is built once here
/// (and dropped) so that what only the problem checks (e.g. initial penetration) is refused too; the
/// first one's sizes go into `sweep`.
std::vector<Scene> valueScenes(const SweepArgs& args, const SweepRange& range, Sweep& sweep) {
  for (const std::string& o : args.overrides)
    if (keyOf(o) == range.key) throw InputError("--set " + o + " conflicts with --set-range " + range.key);
  if (args.tolerance && range.key == "solver.tolerance")
    throw InputError("--tol conflicts with --set-range solver.tolerance");
  const std::vector<std::string> common = withSolverOptions(args.overrides, args.solver, args.tolerance);
  std::vector<Scene> scenes;
  for (std::size_t i = 0; i < range.values.size(); ++i) {
    std::vector<std::string> overrides = common;
    overrides.push_back(range.override(i));
    scenes.push_back(readScene(args.scene, overrides));
    const Problem problem = buildProblem(scenes.back());
    if (i > 0) continue;
    sweep.n_dofs = problem.numDofs();
    sweep.n_contact_nodes = problem.contact.size();
    sweep.n_steps = problem.numSteps();
  }
  return scenes;
}

std::string solverOf(const Scene& first) {
  const std::string solver(first.solver.name());
  if (first.solver.strategy == Strategy::Incremental)
    throw InputError("--solver incremental: a sweep compares warm and cold starts of an iterative strategy, "
                     "and the incremental solver always starts from the unloaded state");
  return solver;
}

std::string commandLine(const SweepArgs& a, const std::string& solver, const fs::path& out) {
  std::string line = "stcontact sweep " + a.scene + " --set-range " + a.range + " --solver " + solver;
  for (const auto& o : a.overrides) line += " --set " + o;
  if (a.tolerance) line += " --tol " + shortNumber(*a.tolerance, 6);
  if (a.no_independent) line += " --no-independent";
  if (a.write_solutions) line += " --write-solutions";
  return line + " --out " + out.string();
}

void describe(Sweep& s, const SweepArgs& args, const SweepRange& range, const Scene& first, const std::string& solver,
              const fs::path& out) {
  s.scene_name = first.name;
  s.scene_file = args.scene;
  s.command = commandLine(args, solver, out);
  s.key = range.key;
  s.solver = solver;
  s.tolerance = first.solver.tolerance();
  s.environment = describeRunEnvironment();
}

/// sweep.png: relaxations and wall time per value, warm against cold (scripts/plots/sweep.gp).
PlotJob sweepPlot(const Sweep& s) {
  return reportPlotJob("sweep.gp",
                       "key=" + gnuplotString(s.key) + "; scene=" + gnuplotString(s.scene_name) + "; solver=" +
                           gnuplotString(s.solver) + "; cold=" + (s.independent() ? "1" : "0"),
                       {"sweep.png"});
}

void printTotals(const Sweep& s) {
  const SweepTotals warm = warmTotals(s);
  std::cout << "warm: " << warm.relaxations << " relaxations, " << warm.sparse_solves << " sparse solves, "
            << shortNumber(warm.wall_s, 3) << " s";
  if (const auto cold = coldTotals(s))
    std::cout << "; cold: " << cold->relaxations << " relaxations, " << cold->sparse_solves << " sparse solves, "
              << shortNumber(cold->wall_s, 3) << " s";
  std::cout << std::endl;
}

}  // namespace

CLI::App* addSweepCommand(CLI::App& app, SweepArgs& args) {
  auto* cmd = app.add_subcommand("sweep", "solve a scene for a range of one parameter, warm-started (docs/sweep.md)");
  cmd->add_option("scene", args.scene, "scene file (TOML)")->required();
  cmd->add_option("--set-range", args.range, "KEY=FROM:TO:COUNT, COUNT evenly spaced values, both ends included")
      ->required();
  cmd->add_option("--solver", args.solver, "strategy (default: the scene's [solver] name, else fas-apriori)");
  cmd->add_option("--set", args.overrides, "override a scene value for every solve: section.key=value")->take_all();
  cmd->add_option("--out", args.out, "report folder (default results/<scene name>/sweep_<KEY>)");
  cmd->add_option("--tol", args.tolerance, toleranceHelp());
  cmd->add_flag("--no-independent", args.no_independent, "warm solves only: no cold solve of each value");
  cmd->add_flag("--write-solutions", args.write_solutions, "write each value's solution into --out/value_<VALUE>/");
  cmd->add_flag("--quiet", args.quiet, "no progress, no per-value lines");
  addThreadsOption(*cmd);
  addProgressIntervalOption(*cmd);
  return cmd;
}

int runSweep(const SweepArgs& args) {
  const SweepRange range = parseSweepRange(args.range);
  Sweep sweep;
  const std::vector<Scene> scenes = valueScenes(args, range, sweep);
  const std::string solver = solverOf(scenes.front());
  const fs::path out =
      args.out ? fs::path(*args.out) : fs::path("results") / scenes.front().name / ("sweep_" + range.key);
  RunFolder folder(out);  // every input checked: now the folder may be locked, written whole at the end
  describe(sweep, args, range, scenes.front(), solver, out);

  TerminalProgress progress(args.quiet);
  const SweepSettings settings{strategyNamed(solver), !args.no_independent,
                               args.write_solutions ? std::optional<fs::path>(folder.path()) : std::nullopt, &progress};
  WarmChain chain;
  for (std::size_t i = 0; i < scenes.size(); ++i) sweep.points.push_back(chain.solveValue(scenes[i], range, i, settings));
  sweep.load_after = loadAverage();
  throwIfInterrupted();
  writeSweep(folder.path(), sweep);

  std::string warning;
  if (!drawPlots(folder.path(), sweepPlot(sweep), warning)) std::cerr << "warning: " << folder.named(warning) << std::endl;
  folder.commit();
  if (!args.quiet) {
    printTotals(sweep);
    std::cout << "report: " << (out / "summary.md").string() << std::endl;
  }
  const SweepTotals warm = warmTotals(sweep);
  const auto cold = coldTotals(sweep);
  const bool all_converged = warm.converged == warm.values && (!cold || cold->converged == cold->values);
  return all_converged ? 0 : 2;
}

}  // namespace stc::cli
