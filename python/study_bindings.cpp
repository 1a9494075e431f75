// stcontact._core.svd, stcontact._core.compare and stcontact._core.true_error: the verification SVD of
// `stcontact svd`, the work-precision comparison of `stcontact compare` and the check of a written
// solution of `stcontact true-error`, through the command line's own code where it
// is shared (studies/compare_runs.hpp, studies/), with the interpreter's lock released.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "stcontact/core/input_error.hpp"
#include "stcontact/io/atomic_file.hpp"
#include "stcontact/io/run_folder.hpp"
#include "stcontact/pgd/space_time_svd.hpp"
#include "stcontact/python/bindings.hpp"
#include "stcontact/python/callback_bridge.hpp"
#include "stcontact/python/numpy_arrays.hpp"
#include "stcontact/python/scene_handle.hpp"
#include "stcontact/studies/compare_plots.hpp"
#include "stcontact/studies/compare_runs.hpp"
#include "stcontact/studies/comparison_writer.hpp"
#include "stcontact/studies/number_format.hpp"
#include "stcontact/studies/reference.hpp"
#include "stcontact/studies/solution_svd.hpp"

namespace stc::python {
namespace {

/// The energy SVD of the incremental solution with the options `stcontact svd` uses
/// (studies/solution_svd.hpp). Lock released; a Ctrl-C stops the incremental solve.
pgd::SpaceTimeSvd energySvdOfSolution(const Problem& problem, int modes, CallbackBridge& bridge) {
  py::gil_scoped_release unlocked;
  SolutionHistory history;  // Ctrl-C in the Delassus columns too (CallbackBridge::runStoppable)
  if (!bridge.runStoppable([&] { history = incrementalHistory(problem, bridge.signalsOnly()); })) return {};
  if (bridge.interrupted()) return {};
  if (!history.solved.summary.converged())
    throw std::runtime_error("the incremental solver did not converge (" + history.solved.summary.message +
                             "): no SVD");
  return arpackEnergySvd(history.U, problem.stiffness, modes);
}

/// The columns of singular_values.csv, time_functions.csv (ν_i √σ_i) and the modes of modes.vtu
/// (Υ_i √σ_i, n × modes) (pgd/svd_tables.hpp), and the energy levels of svd_summary.json.
py::dict svdDict(pgd::SpaceTimeSvd&& svd, const Problem& problem, int modes) {
  const int r = svd.size();
  modes = std::min(modes, r);
  Eigen::VectorXd fraction(r), cumulative(r);
  for (int i = 0; i < r; ++i) {
    fraction[i] = svd.energyFraction(i);
    cumulative[i] = svd.cumulativeEnergy(i);
  }
  const Eigen::VectorXd scale = svd.sigma.head(modes).cwiseSqrt();
  py::dict levels;
  const std::pair<const char*, double> energy_levels[] = {{"99%", 0.99}, {"99.9%", 0.999}, {"99.99%", 0.9999}};
  for (const auto& [label, level] : energy_levels) levels[label] = svd.modesFor(level);
  py::dict out;
  out["time_functions"] = movedToNumpy(Eigen::MatrixXd(svd.time.leftCols(modes) * scale.asDiagonal()));
  out["spatial_modes"] = movedToNumpy(Eigen::MatrixXd(svd.space.leftCols(modes) * scale.asDiagonal()));
  out["energy_fraction"] = movedToNumpy(std::move(fraction));
  out["cumulative_energy"] = movedToNumpy(std::move(cumulative));
  out["modes_for_energy"] = levels;
  out["total_energy"] = svd.total_energy;
  out["resolved"] = svd.resolved;
  out["operator_applications"] = svd.operator_applications;
  out["times"] = movedToNumpy(std::vector<double>(problem.times));
  out["sigma"] = movedToNumpy(std::move(svd.sigma));
  return out;
}

py::dict svd(const SceneHandle& handle, int modes, const std::vector<std::string>& sets, std::optional<int> threads) {
  requireOneProcess("svd");
  const ThreadsForCall thread_count(threads);
  const SceneHandle run = handle.withOverrides(sets);
  const std::shared_ptr<const Problem> problem = run.problem();
  checkSvdSizes(problem->numSteps(), modes);
  CallbackBridge bridge;
  pgd::SpaceTimeSvd result = energySvdOfSolution(*problem, modes, bridge);
  bridge.rethrowPending();
  return svdDict(std::move(result), *problem, modes);
}

struct CompareOptions {
  std::vector<std::string> solvers;  ///< empty: every available strategy
  int repeats = 3;
  std::optional<double> tolerance;
  std::vector<std::string> sets;
  std::optional<int> threads;
  std::optional<std::filesystem::path> out;
};

std::string joined(const std::vector<std::string>& names, const std::string& separator) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : separator) + name;
  return text;
}

/// The call as the report's "command" line names it.
std::string callText(const SceneHandle& handle, const std::vector<Strategy>& solvers, const CompareOptions& o) {
  std::string text = "stcontact.compare('" + handle.source().string() + "', solvers='" + joinedNames(solvers) +
                     "', repeats=" + std::to_string(o.repeats);
  if (!o.sets.empty()) text += ", sets=['" + joined(o.sets, "', '") + "']";
  if (o.tolerance) text += ", tol=" + shortNumber(*o.tolerance, 6);
  return text + ")";
}

/// The runs of `stcontact compare` (cli/compare_command.cpp): the reference, then each strategy.
void measureEach(Comparison& comparison, const Problem& problem, const SolverSpec& spec,
                 const std::vector<Strategy>& solvers, int repeats, CallbackBridge& bridge) {
  const ReferenceSolution reference = computeReference(problem, nullptr);
  comparison.reference_s = reference.total_s;
  const CompareContext context{problem, spec, reference, repeats, nullptr, {}, bridge.signalsOnly()};
  for (const Strategy solver : solvers) {
    if (bridge.interrupted()) return;
    comparison.strategies.push_back(measureStrategy(solver, context));
  }
  if (bridge.interrupted()) return;
  comparison.memory_method = describeMemoryMethod(comparison.strategies.front().memory.since_reset);
  comparison.load_after = loadAverage();
}

/// measureEach with the lock released; stopped by Ctrl-C, its KeyboardInterrupt pending in `bridge`.
void measureAll(Comparison& comparison, const Problem& problem, const SolverSpec& spec,
                const std::vector<Strategy>& solvers, int repeats, CallbackBridge& bridge) {
  py::gil_scoped_release unlocked;
  bridge.runStoppable([&] { measureEach(comparison, problem, spec, solvers, repeats, bridge); });
}

/// The points of one run as arrays (work_precision.csv's columns).
py::dict pointArrays(const std::vector<WorkPoint>& points) {
  std::vector<int> iteration, relaxations;
  std::vector<double> sparse_solves, indicator, error, wall_s;
  for (const WorkPoint& p : points) {
    iteration.push_back(p.iteration);
    relaxations.push_back(p.relaxations);
    sparse_solves.push_back(static_cast<double>(p.sparse_solves));
    indicator.push_back(p.indicator);
    error.push_back(p.error.value_or(std::numeric_limits<double>::quiet_NaN()));
    wall_s.push_back(p.wall_s);
  }
  py::dict arrays;
  arrays["iteration"] = movedToNumpy(std::move(iteration));
  arrays["relaxations"] = movedToNumpy(std::move(relaxations));
  arrays["sparse_solves"] = movedToNumpy(std::move(sparse_solves));
  arrays["indicator"] = movedToNumpy(std::move(indicator));
  arrays["error"] = movedToNumpy(std::move(error));
  arrays["wall_s"] = movedToNumpy(std::move(wall_s));
  return arrays;
}

py::dict strategyDict(const StrategyMeasurement& m) {
  py::list runs;
  for (const TimedRun& run : m.runs)
    runs.append(py::dict(py::arg("repeat") = run.repeat, py::arg("total_s") = run.total_s,
                         py::arg("points") = pointArrays(run.points)));
  py::dict s;
  s["solver"] = m.solver;
  s["reference_point"] = m.reference_point;
  s["termination"] = toString(m.termination);
  s["message"] = m.message;
  s["iterations"] = m.iterations;
  s["relaxations"] = m.relaxations;
  s["indicator"] = m.indicator;
  s["final_error"] = m.final_error;
  s["final_error_estimate"] = m.final_error_estimate;
  s["sparse_solves"] = m.sparse_solves;
  s["best_error"] = m.best_error;
  s["error_run_s"] = m.error_run_s;
  s["prerequisite_s"] = m.prerequisite_s;
  s["errors_matched"] = m.errors_matched;
  s["peak_rss_mb"] = m.memory.peak_mb;
  s["rss_growth_mb"] = m.memory.growthMb();
  s["runs"] = runs;
  return s;
}

py::dict comparisonDict(const Comparison& c) {
  py::list strategies;
  for (const StrategyMeasurement& m : c.strategies) strategies.append(strategyDict(m));
  py::dict out;
  out["scene"] = c.scene_name;
  out["n_dofs"] = c.n_dofs;
  out["n_contact_nodes"] = c.n_contact_nodes;
  out["n_steps"] = c.n_steps;
  out["tolerance"] = c.tolerance;
  out["repeats"] = c.repeats;
  out["reference_s"] = c.reference_s;
  out["strategies"] = strategies;
  out["summary_csv"] = summaryCsv(c);
  out["work_precision_csv"] = workPrecisionCsv(c);
  out["summary_markdown"] = summaryMarkdown(c);
  return out;
}

py::dict compare(const SceneHandle& handle, const CompareOptions& o) {
  requireOneProcess("compare");
  const ThreadsForCall thread_count(o.threads);
  if (o.repeats < 1) throw InputError("--repeats must be >= 1");
  const SceneHandle run = handle.withOverrides(o.sets);
  Scene scene = run.scene();
  const std::vector<Strategy> solvers =
      solverList(o.solvers.empty() ? std::nullopt : std::optional<std::string>(joined(o.solvers, ",")));
  if (o.tolerance) {
    if (!(*o.tolerance > 0.0)) throw InputError("--tol must be > 0");
    scene.solver.setTolerance(*o.tolerance);
  }
  std::optional<RunFolder> folder;  // checked and locked before the runs, written whole after them
  if (o.out) folder.emplace(*o.out);
  const std::shared_ptr<const Problem> problem = run.problem();
  Comparison comparison =
      describeComparison(handle.source().string(), callText(handle, solvers, o), scene, *problem, o.repeats);
  CallbackBridge bridge;
  measureAll(comparison, *problem, scene.solver, solvers, o.repeats, bridge);
  bridge.rethrowPending();
  if (folder) {
    writeComparison(folder->path(), comparison);
    std::string warning;
    if (!drawWorkPrecisionPlots(folder->path(), comparison, warning) &&
        PyErr_WarnEx(PyExc_RuntimeWarning, folder->named(warning).c_str(), 1) != 0)
      throw py::error_already_set();
    folder->commit();
  }
  return comparisonDict(comparison);
}

// A NaN of solution.h5 (no estimate, no true error measured) as None.
py::object numberOrNone(double x) { return std::isfinite(x) ? py::object(py::float_(x)) : py::none(); }

/// `stcontact true-error` (studies/reference.hpp, measureStoredSolution) on `handle`'s scene. Lock
/// released for the reference and the measure; a Ctrl-C stops the reference.
py::dict trueError(const SceneHandle& handle, const std::filesystem::path& solution, const std::vector<std::string>& sets,
                   std::optional<int> threads) {
  requireOneProcess("true_error");
  const ThreadsForCall thread_count(threads);
  const SceneHandle run = handle.withOverrides(sets);
  const std::shared_ptr<const Problem> problem = run.problem();
  CallbackBridge bridge;
  std::string warning;
  std::optional<StoredSolutionError> measured;
  {
    py::gil_scoped_release unlocked;
    PreparedOperators operators(run.scene().solver.linearAtTolerance());
    bridge.runStoppable([&] {
      measured = measureStoredSolution(*problem, run.scene().model_json, solution, operators, bridge.signalsOnly(),
                                       warning);
    });
  }
  bridge.rethrowPending();
  if (!measured) throw std::runtime_error(warning);
  py::dict out;
  out["error"] = measured->error;
  out["error_estimate"] = numberOrNone(measured->stored.error_estimate);
  out["run_error"] = numberOrNone(measured->stored.error);
  out["solver"] = measured->stored.solver;
  out["seconds"] = measured->seconds;
  return out;
}

}  // namespace

void bindStudies(py::module_& module) {
  module.def("true_error", &trueError, py::arg("scene"), py::arg("solution"), py::arg("sets"), py::arg("threads"));
  module.def("svd", &svd, py::arg("scene"), py::arg("modes"), py::arg("sets"), py::arg("threads"));
  module.def(
      "compare",
      [](const SceneHandle& scene, std::vector<std::string> solvers, int repeats, std::optional<double> tol,
         std::vector<std::string> sets, std::optional<int> threads, std::optional<std::filesystem::path> out) {
        return compare(scene, {std::move(solvers), repeats, tol, std::move(sets), threads, std::move(out)});
      },
      py::arg("scene"), py::arg("solvers"), py::arg("repeats"), py::arg("tol"), py::arg("sets"), py::arg("threads"),
      py::arg("out"));
}

}  // namespace stc::python
