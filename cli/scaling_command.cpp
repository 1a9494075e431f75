// stcontact scaling SCENE: for every size of a mesh series (arc nodes, at the scene's instants) and
// a time series (instants, at the scene's mesh), the comparison of `stcontact compare` (same runs,
// compare_runs.hpp) with every iterative run stopped at the target true error; then growth
// exponents, crossover against incremental and memory (studies/scaling_study.hpp). Writes
// scaling.csv, summary.md, sizes/<size>/ and, through gnuplot, the plots. docs/scaling.md.
#include "stcontact/cli/scaling_command.hpp"
#include "stcontact/cli/stopping_help.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <iostream>

#include "stcontact/cli/commands.hpp"
#include "stcontact/cli/compare_command.hpp"
#include "stcontact/cli/terminal_progress.hpp"
#include "stcontact/cli/threads_option.hpp"
#include "stcontact/core/clock.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/core/interruption.hpp"
#include "stcontact/io/run_folder.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/studies/compare_runs.hpp"
#include "stcontact/studies/number_format.hpp"
#include "stcontact/studies/scaling_plots.hpp"
#include "stcontact/studies/scaling_runs.hpp"
#include "stcontact/studies/scaling_writer.hpp"

namespace stc::cli {
namespace {

using Clock = std::chrono::steady_clock;

/// The mesh series' generator key and its sizes: arc_nodes (half_disc, half_disc_slab) or divisions
/// (half_ball); the option of the other kind must not be given.
struct MeshSeries {
  std::string parameter;
  std::vector<int> sizes;
  int base = 0;  // the scene's own value
};

/// The items of "101,201" (split by the option's delimiter) as sizes, each >= `minimum`; "none" (or
/// an empty list) is an empty series.
std::vector<int> sizeList(const std::vector<std::string>& items, const std::string& option, int minimum) {
  std::vector<int> sizes;
  if (items == std::vector<std::string>{"none"} || items == std::vector<std::string>{""}) return sizes;
  for (const std::string& item : items) {
    std::size_t used = 0;
    int value = 0;
    try {
      value = std::stoi(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || item.find_first_not_of(" \t", used) != std::string::npos)
      throw InputError(option + ": '" + item + "' is not an integer");
    if (value < minimum) throw InputError(option + ": " + item + " must be >= " + std::to_string(minimum));
    if (std::find(sizes.begin(), sizes.end(), value) != sizes.end())
      throw InputError(option + ": " + item + " is listed twice");
    sizes.push_back(value);
  }
  return sizes;
}

MeshSeries meshSeries(const ScalingArgs& a, const Scene& base) {
  const bool ball = base.mesh.generator == "half_ball";
  const bool disc = base.mesh.generator == "half_disc" || base.mesh.generator == "half_disc_slab";
  const std::vector<std::string>& own = ball ? a.divisions : a.arc_nodes;
  const std::vector<std::string>& other = ball ? a.arc_nodes : a.divisions;
  if (!other.empty() && other != std::vector<std::string>{"none"})
    throw InputError(std::string(ball ? "--arc-nodes" : "--divisions") + " does not apply to a scene with the " +
                     (base.mesh.generator.empty() ? "mesh file" : base.mesh.generator + " generator") +
                     (ball ? " (give --divisions)" : disc ? " (give --arc-nodes)" : ""));
  MeshSeries s;
  s.parameter = ball ? "divisions" : "arc_nodes";
  s.base = ball ? base.mesh.divisions : disc ? base.mesh.arc_nodes : 0;
  if (!ball && !disc) {  // a mesh file: the time series only, said explicitly
    if (own != std::vector<std::string>{"none"})
      throw InputError("--arc-nodes needs a scene with the half_disc, half_disc_slab or half_ball mesh generator "
                       "(give --arc-nodes none otherwise)");
    return s;
  }
  const std::vector<std::string> defaults =
      ball ? std::vector<std::string>{"6", "8", "12"} : std::vector<std::string>{"101", "201", "401", "801"};
  s.sizes = sizeList(own.empty() ? defaults : own, ball ? "--divisions" : "--arc-nodes", ball ? 2 : 3);
  return s;
}

/// The mesh series at the base instants, then the time series at the base mesh; a size in both runs once.
std::vector<ScalingSize> planSizes(const MeshSeries& mesh, const ScalingArgs& a, const Scene& base) {
  std::vector<ScalingSize> plan;
  const std::vector<int> steps = sizeList(a.steps, "--steps", 2);
  if (mesh.sizes.empty() && steps.empty()) throw InputError("the mesh and time series are both empty: nothing to run");
  for (int n : mesh.sizes) plan.push_back({n, base.time.steps, true, false});
  for (int m : steps) {
    auto same = std::find_if(plan.begin(), plan.end(),
                             [&](const ScalingSize& p) { return p.mesh_size == mesh.base && p.steps == m; });
    if (same != plan.end())
      same->in_time = true;
    else
      plan.push_back({mesh.base, m, false, true});
  }
  return plan;
}

std::string commaList(const std::vector<std::string>& items) {
  std::string list;
  for (const auto& item : items) list += (list.empty() ? "" : ",") + item;
  return list;
}

std::string commandLine(const ScalingArgs& a, const std::vector<std::string>& solvers,
                        const std::filesystem::path& out) {
  std::string line = "stcontact scaling " + a.scene + " --solvers " + commaList(solvers) + " --out " + out.string() +
                     " --repeats " + std::to_string(a.repeats) +
                     (a.divisions.empty() ? "" : " --divisions '" + commaList(a.divisions) + "'") +
                     (a.arc_nodes.empty() ? "" : " --arc-nodes '" + commaList(a.arc_nodes) + "'") + " --steps '" +
                     commaList(a.steps) + "' --target-error " + targetLabel(a.target_error) + " --tol " +
                     shortNumber(a.tolerance, 6);
  if (a.max_iterations) line += " --max-iterations " + std::to_string(*a.max_iterations);
  if (a.time_cap_s) line += " --time-cap " + shortNumber(*a.time_cap_s, 6);
  if (a.only_at_tolerance) line += " --only-at-tolerance";
  for (const auto& o : a.overrides) line += " --set " + o;
  return line;
}

Scene sceneAt(const ScalingArgs& a, const MeshSeries& mesh, const ScalingSize& size) {
  std::vector<std::string> overrides = a.overrides;
  if (size.in_mesh) overrides.push_back("mesh." + mesh.parameter + "=" + std::to_string(size.mesh_size));
  overrides.push_back("time.steps=" + std::to_string(size.steps));
  Scene scene = readScene(a.scene, overrides);
  scene.solver.setTolerance(a.tolerance);
  if (a.max_iterations) scene.solver.setMaxIterations(*a.max_iterations);
  return scene;
}

void validate(const ScalingArgs& a) {
  if (a.repeats < 1) throw InputError("--repeats must be >= 1");
  if (!(a.target_error > 0.0 && a.target_error < 1.0)) throw InputError("--target-error must be in (0, 1)");
  if (!(a.tolerance > 0.0)) throw InputError("--tol must be > 0");
  if (a.max_iterations && *a.max_iterations < 1) throw InputError("--max-iterations must be >= 1");
  if (a.time_cap_s && !(*a.time_cap_s > 0.0)) throw InputError("--time-cap must be > 0");
  if (a.time_cap_s && a.only_at_tolerance)
    throw InputError("--time-cap stops the first-reach error runs, which --only-at-tolerance leaves out");
}

}  // namespace

CLI::App* addScalingCommand(CLI::App& app, ScalingArgs& a) {
  auto* cmd = app.add_subcommand("scaling", "time to a true error against mesh and time-grid size (docs/scaling.md)");
  cmd->add_option("scene", a.scene, "scene file (TOML)")->required();
  cmd->add_option("--solvers", a.solvers, "comma-separated strategies (default: every available one)");
  cmd->add_option("--out", a.out, "report folder (default results/<scene name>/scaling)");
  cmd->add_option("--repeats", a.repeats, "timed runs per strategy and size, medians over them")->capture_default_str();
  cmd->add_option("--arc-nodes", a.arc_nodes,
                  "mesh series of a half_disc or half_disc_slab scene: arc nodes, at the scene's instants (default "
                  "101,201,401,801; 'none': no series)")
      ->delimiter(',');
  cmd->add_option("--divisions", a.divisions,
                  "mesh series of a half_ball scene: divisions, at the scene's instants (default 6,8,12; 'none': no "
                  "series)")
      ->delimiter(',');
  cmd->add_option("--steps", a.steps, "time series: instants m, at the scene's mesh ('none': no series)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--target-error", a.target_error, "true error whose time is measured")->capture_default_str();
  cmd->add_option("--tol", a.tolerance, "tolerance on the error estimate")->capture_default_str();
  cmd->add_option("--max-iterations", a.max_iterations, maxIterationsHelp());
  cmd->add_option("--time-cap", a.time_cap_s,
                  "seconds on the solver's clock (the true-error measure left out) after which an error run "
                  "stops: \"not reached\" (default: none)");
  cmd->add_flag("--only-at-tolerance", a.only_at_tolerance,
               "run only the solves at tolerance --target-error (what a user gets), not the first-reach "
               "diagnostic: the exponents, crossovers and plots on their times");
  cmd->add_option("--set", a.overrides, "override a scene value for every size: section.key=value")->take_all();
  cmd->add_flag("--quiet", a.quiet, "no progress, no final report");
  addThreadsOption(*cmd);
  addProgressIntervalOption(*cmd);
  return cmd;
}

int runScaling(const ScalingArgs& a) {
  const auto start = Clock::now();
  validate(a);
  const Scene base = readScene(a.scene, a.overrides);
  const MeshSeries mesh = meshSeries(a, base);
  const std::vector<ScalingSize> plan = planSizes(mesh, a, base);
  ScalingStudy study;
  study.solvers = strategyNamesOf(solverList(a.solvers));
  const std::filesystem::path out =
      a.out ? std::filesystem::path(*a.out) : std::filesystem::path("results") / base.name / "scaling";
  RunFolder folder(out);  // checked and locked before the runs, written whole after them
  study.scene_name = base.name;
  study.scene_file = a.scene;
  study.mesh_parameter = mesh.parameter;
  study.command = commandLine(a, study.solvers, out);
  study.target_error = a.target_error;
  study.tolerance = a.tolerance;
  study.repeats = a.repeats;
  study.first_reach = !a.only_at_tolerance;
  study.time_cap_s = a.time_cap_s;
  study.environment = describeRunEnvironment();
  TerminalProgress progress(a.quiet);
  EarlyStop stop;
  stop.target_error = a.target_error;
  stop.time_cap_s = a.time_cap_s;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    if (!a.quiet)
      std::cout << "[" << i + 1 << "/" << plan.size() << "] " << mesh.parameter << " " << plan[i].mesh_size
                << ", steps " << plan[i].steps << std::endl;
    study.points.push_back(measureScalingSize(sceneAt(a, mesh, plan[i]), plan[i], study, stop, &progress));
  }
  study.memory_method = study.points.front().comparison.memory_method;
  study.load_after = loadAverage();
  study.run_s = secondsSince(start);
  throwIfInterrupted();
  writeScaling(folder.path(), study);
  std::string warning;
  if (!drawScalingPlots(folder.path(), study, warning)) std::cerr << "warning: " << folder.named(warning) << std::endl;
  folder.commit();
  if (!a.quiet) std::cout << "report: " << (out / "summary.md").string() << std::endl;
  return 0;
}

}  // namespace stc::cli
