// stcontact._core.solve: one strategy on one scene, with the command line's options (--solver,
// --tol, --max-iterations, --set, --no-reference, --threads, --out), a warm start and a
// per-iteration callback; the solve runs with the interpreter's lock released (callback_bridge.hpp).
// The result is a dict of NumPy arrays and texts that the Python class SolveResult wraps; its
// Problem and the callback's IterationRecords pickle.
#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "stcontact/core/memory.hpp"
#include "stcontact/io/atomic_file.hpp"
#include "stcontact/io/contact_tables.hpp"
#include "stcontact/io/frame_fields.hpp"
#include "stcontact/io/run_folder.hpp"
#include "stcontact/io/run_writer.hpp"
#include "stcontact/operators/displacement.hpp"
#include "stcontact/python/bindings.hpp"
#include "stcontact/python/callback_bridge.hpp"
#include "stcontact/python/numpy_arrays.hpp"
#include "stcontact/python/scene_handle.hpp"
#include "stcontact/solver/warm_start.hpp"
#include "stcontact/strategies/registry.hpp"
#include "stcontact/studies/reference.hpp"
#include "stcontact/studies/solve_on_ranks.hpp"
#include "stcontact/studies/solve_options.hpp"
#include "stcontact/version.hpp"

namespace stc::python {
namespace {

using ProblemPtr = std::shared_ptr<const Problem>;

struct SolveOptions {
  std::optional<std::string> solver;
  std::optional<double> tolerance;
  std::optional<int> max_iterations;
  std::vector<std::string> sets;
  bool reference = true;
  std::optional<int> threads;
  std::optional<std::filesystem::path> out;
  bool spatial_modes = true;  ///< SolveInputs::spatial_modes
};

/// A warm start as the caller passed it: a previous result's arrays (any may be None).
struct WarmStart {
  using Matrix = std::optional<Eigen::MatrixXd>;
  Matrix forces, displacements, basis_seed;
};

/// The problem a result was solved on, kept alive by the result (Python: stcontact._core.Problem).
/// It pickles as the scene it was assembled from (overrides and solve options included), assembled
/// again on first use after unpickling.
struct ProblemRef {
  SceneHandle scene;
  ProblemPtr problem() const { return scene.problem(); }
};

/// The start history and basis seed for `problem`; ValueError when a part is missing or its sizes
/// do not fit (stc::requireFits names both sizes).
void applyWarmStart(WarmStart& warm, const Problem& problem, std::optional<InterfaceHistory>& start,
                    SolveInputs& inputs) {
  if (warm.forces.has_value() != warm.displacements.has_value())
    throw std::invalid_argument("a warm start needs both the interface forces and the interface displacements");
  // Named as the caller wrote them (a SolveResult's arrays, edited in place: NaN reached every file).
  if (warm.forces) requireFinite(*warm.forces, "start.interface_forces");
  if (warm.displacements) requireFinite(*warm.displacements, "start.interface_displacements");
  if (warm.basis_seed) requireFinite(*warm.basis_seed, "start.interface_directions");
  if (warm.forces) {
    start = InterfaceHistory{std::move(*warm.displacements), std::move(*warm.forces)};
    requireFits(*start, problem);
    inputs.start = &*start;
  }
  if (warm.basis_seed && warm.basis_seed->cols() > 0) {
    requireFits(*warm.basis_seed, problem);
    inputs.basis_seed = &*warm.basis_seed;
  }
}

/// The value history.csv writes, NaN where it leaves the cell empty (an estimate not yet known: +∞).
double estimateOrNan(double error_estimate) {
  return std::isfinite(error_estimate) ? error_estimate : std::numeric_limits<double>::quiet_NaN();
}

/// history.csv's columns (src/io/run_writer.hpp) and the sparse solves, one entry per record;
/// the true error and the error estimate are NaN where the file's cell is empty.
py::dict historyArrays(const SolveSummary& summary) {
  std::vector<int> iteration, relaxations, rank, sparse_solves;
  std::vector<long long> krylov_iterations;
  std::vector<double> indicator, error, wall_s, error_estimate;
  for (const IterationRecord& r : summary.history) {
    iteration.push_back(r.iteration);
    relaxations.push_back(r.relaxations);
    indicator.push_back(r.indicator);
    error.push_back(r.error.value_or(std::numeric_limits<double>::quiet_NaN()));
    rank.push_back(r.rank);
    sparse_solves.push_back(r.sparse_solves);
    krylov_iterations.push_back(r.krylov_iterations);
    wall_s.push_back(r.wall_s);
    error_estimate.push_back(estimateOrNan(r.error_estimate));
  }
  py::dict history;
  history["iteration"] = movedToNumpy(std::move(iteration));
  history["relaxations"] = movedToNumpy(std::move(relaxations));
  history["indicator"] = movedToNumpy(std::move(indicator));
  history["error"] = movedToNumpy(std::move(error));
  history["rank"] = movedToNumpy(std::move(rank));
  history["wall_s"] = movedToNumpy(std::move(wall_s));
  history["error_estimate"] = movedToNumpy(std::move(error_estimate));
  history["sparse_solves"] = movedToNumpy(std::move(sparse_solves));
  history["krylov_iterations"] = movedToNumpy(std::move(krylov_iterations));
  return history;
}

/// reactions.csv's columns (stc::reactionTable, the writer's own rows).
py::dict reactionArrays(const Problem& problem, const SolveResult& result, const InterfaceTable& interface) {
  ReactionTable table = reactionTable(problem, result, interface);
  std::vector<int> step(table.t.size());
  for (std::size_t k = 0; k < step.size(); ++k) step[k] = static_cast<int>(k);
  py::dict reactions;
  reactions["step"] = movedToNumpy(std::move(step));
  reactions["t"] = movedToNumpy(std::move(table.t));
  reactions["normal_force"] = movedToNumpy(std::move(table.normal_force));
  reactions["tangential_force"] = movedToNumpy(std::move(table.tangential_force));
  if (problem.dimension == 3) reactions["tangential_force_2"] = movedToNumpy(std::move(table.tangential_force_2));
  reactions["contact_xmin"] = movedToNumpy(std::move(table.contact_xmin));
  reactions["contact_xmax"] = movedToNumpy(std::move(table.contact_xmax));
  reactions["n_contact"] = movedToNumpy(std::move(table.n_contact));
  reactions["n_slip"] = movedToNumpy(std::move(table.n_slip));
  const char* force_names[] = {"force_x", "force_y", "force_z"};
  for (Eigen::Index a = 0; a < table.force.rows(); ++a) {
    reactions[force_names[a]] = movedToNumpy(Eigen::VectorXd(table.force.row(a).transpose()));
  }
  return reactions;
}

/// contact.csv's per-node columns beside λ (stc::interfaceTable, the writer's own): the tributary
/// lengths or areas ℓ_i, and n_C × m gap and state (0 open, 1 stick, 2 slip), (d − 1) n_C × m slip
/// (rows (d − 1) i + a), in the library's layout (column k: instant k).
py::dict contactArrays(const Problem& problem, const InterfaceTable& table) {
  const int n = table.nodes, m = table.steps, t = table.tangential;
  Eigen::MatrixXd gap(n, m), slip(static_cast<Eigen::Index>(t) * n, m);
  Eigen::MatrixXi state(n, m);
  for (int k = 0; k < m; ++k)
    for (int i = 0; i < n; ++i) {
      const auto at = static_cast<std::size_t>(k) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i);
      gap(i, k) = table.gap[at];
      state(i, k) = table.state[at];
      for (int a = 0; a < t; ++a) slip(t * i + a, k) = table.slip[at * static_cast<std::size_t>(t) + static_cast<std::size_t>(a)];
    }
  py::dict contact;
  const std::vector<long long> tags = nodeTags(problem.body);
  std::vector<long long> contact_tags;
  for (int node : problem.contact.nodes) contact_tags.push_back(tags[static_cast<std::size_t>(node)]);
  contact["node_tags"] = movedToNumpy(std::move(contact_tags));
  contact["tributary"] = movedToNumpy(Eigen::VectorXd(problem.contact.tributary));
  contact["gap"] = movedToNumpy(std::move(gap));
  contact["slip"] = movedToNumpy(std::move(slip));
  contact["state"] = movedToNumpy(std::move(state));
  return contact;
}

/// Everything the Python SolveResult holds. Texts and tables first, while `result` is whole; then
/// the large matrices are moved into their arrays. Call within the call's thread count (the
/// summary records it); `peaks`: every rank's peak memory so far, in rank order.
py::dict resultDict(const SceneHandle& run, SolveResult&& result, const PreparedOperators& operators,
                    std::vector<double> peaks) {
  const Scene& scene = run.scene();
  const ProblemPtr problem = run.problem();
  py::dict out;
  out["solver"] = std::string(scene.solver.name());
  out["dimension"] = problem->dimension;
  out["summary_json"] =
      summaryJson(*problem, result.summary, {scene.parameters_json, STC_VERSION, std::move(peaks), {}, {}},
                  operators.preparations());
  out["history"] = historyArrays(result.summary);
  const InterfaceTable interface = interfaceTable(*problem, result);  // the states, once for both
  out["reactions"] = reactionArrays(*problem, result, interface);
  out["contact"] = contactArrays(*problem, interface);
  out["times"] = movedToNumpy(std::vector<double>(problem->times));
  out["contact_nodes"] = movedToNumpy(std::vector<int>(problem->contact.nodes));
  out["master_nodes"] = movedToNumpy(std::vector<int>(problem->contact.master_nodes));
  out["forces"] = movedToNumpy(std::move(result.interface.lambda));
  out["displacements"] = movedToNumpy(std::move(result.interface.v));
  out["spatial_modes"] = movedToNumpy(std::move(result.spatial_modes));
  out["interface_directions"] = movedToNumpy(std::move(result.interface_directions));
  out["problem"] = ProblemRef{run};
  return out;
}

/// The reference (unless not wanted, see solve_command.cpp), then the strategy.
SolveResult solveWithReference(const Problem& problem, const Scene& scene, bool with_reference, SolveInputs inputs,
                               CallbackBridge& bridge, std::string& warning, std::optional<double>& reference_s) {
  std::unique_ptr<ErrorReference> reference;
  if (computesReference(problem, scene.solver.strategy,
                        with_reference ? ReferenceWish::UpToMaxNodes : ReferenceWish::Never)) {
    const auto begun = std::chrono::steady_clock::now();
    reference = solveReference(problem, bridge.signalsOnly(), warning, *inputs.operators);
    reference_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
  }
  if (bridge.interrupted()) return {};
  inputs.reference = reference.get();
  inputs.converged_lambda = reference ? &reference->referenceForces() : nullptr;
  inputs.callback = bridge.withUserCallback();
  return solve(problem, scene.solver, inputs);
}

/// solveWithReference with the lock released and Ctrl-C heard where the solve makes no record too
/// (src/core/interruption.hpp, StopProbe): stopped there, it returns nothing, its KeyboardInterrupt
/// pending in `bridge`.
SolveResult runSolve(const Problem& problem, const Scene& scene, bool with_reference, SolveInputs inputs,
                     CallbackBridge& bridge, std::string& warning, std::optional<double>& reference_s) {
  py::gil_scoped_release unlocked;
  SolveResult result;
  bridge.runStoppable(
      [&] { result = solveWithReference(problem, scene, with_reference, std::move(inputs), bridge, warning, reference_s); });
  return result;
}

py::dict solve(const SceneHandle& handle, const SolveOptions& options, WarmStart warm, py::object callback) {
  const auto started = std::chrono::steady_clock::now();
  const Ranks ranks = ranksForCall(options.threads);  // under mpirun -np N: one of N ranks
  const ThreadsForCall threads(options.threads);
  const SceneHandle run = handle.withOverrides(
      withSolverOptions(options.sets, options.solver, options.tolerance, options.max_iterations));
  const Scene& scene = run.scene();
  const ProblemPtr problem = run.problem();
  const LinearSolverOptions linear = scene.solver.linearAtTolerance();  // before anything is created
  requireBackendForRanks(scene, ranks);
  std::optional<RunFolder> folder;  // rank 0's: checked and locked before the solve, written whole after it
  if (options.out && ranks.writes()) folder.emplace(*options.out);
  std::optional<InterfaceHistory> start;
  // each operator prepared once, by the scene's backend: the reference, the solve, the frames
  PreparedOperators operators(linear);
  SolveInputs inputs;
  inputs.spatial_modes = options.spatial_modes;
  inputs.separated_displacement = options.out && scene.output.frames;  // the frames come from it
  inputs.operators = &operators;
  applyWarmStart(warm, *problem, start, inputs);

  CallbackBridge bridge(std::move(callback));
  std::string warning;
  std::optional<double> reference_s;
  SolveResult result = runSolve(*problem, scene, options.reference, inputs, bridge, warning, reference_s);
  bridge.rethrowPending();
  std::vector<double> peaks = valuesOfEveryRank(peakResidentBytes());  // every rank takes part
  if (!warning.empty() && PyErr_WarnEx(PyExc_RuntimeWarning, warning.c_str(), 1) != 0) throw py::error_already_set();
  if (folder) {
    std::string note;
    const OutputSpec output = outputsOnRanks(scene, ranks, result, note);
    if (!note.empty() && PyErr_WarnEx(PyExc_RuntimeWarning, note.c_str(), 1) != 0) throw py::error_already_set();
    writeRunOutputs(folder->path(), *problem, result,
                    {scene.parameters_json, STC_VERSION, peaks, started, reference_s, scene.model_json}, output,
                    operators);
    folder->commit();
  }
  return resultDict(run, std::move(result), operators, std::move(peaks));
}

/// Full displacements n × m (dof d j: u_x of node j, d j + 1: u_y, d j + 2: u_z in 3D) rebuilt from the forces.
py::array displacementsFromForces(const ProblemRef& ref, const Eigen::MatrixXd& forces) {
  const ProblemPtr problem = ref.problem();
  if (forces.rows() != problem->contact.rows() || forces.cols() != problem->numSteps()) {
    std::ostringstream message;
    message << "forces are " << forces.rows() << " x " << forces.cols() << ", the problem's interface "
            << problem->contact.rows() << " x " << problem->numSteps();
    throw std::invalid_argument(message.str());
  }
  Eigen::MatrixXd u;
  {
    py::gil_scoped_release unlocked;
    PreparedOperators operators;
    u = fullDisplacements(*problem, *operators.stiffnessFree(*problem), forces);
    for (int k = 0; k < problem->numSteps(); ++k) problem->addFrameMotion(u.col(k), k);  // a moving obstacle's frame
  }
  return movedToNumpy(std::move(u));
}

/// The stress of every element from a full displacement (n_dofs, the layout of displacementsFromForces):
/// (n_e × 6 in VTK's order xx, yy, zz, xy, yz, xz; n_e von Mises), as the frames hold them.
py::tuple stressesOf(const ProblemRef& ref, const Eigen::VectorXd& u) {
  const ProblemPtr problem = ref.problem();
  if (u.size() != problem->numDofs())
    throw std::invalid_argument("u has " + std::to_string(u.size()) + " entries, the problem " +
                                std::to_string(problem->numDofs()) + " dofs");
  std::vector<CellField> fields = elementStressFields(*problem, u);
  Eigen::MatrixXd stress = fields[0].values.transpose(), von_mises = fields[1].values.transpose();
  return py::make_tuple(movedToNumpy(std::move(stress)), movedToNumpy(Eigen::VectorXd(von_mises.col(0))));
}

/// The estimate as the record's Python attribute: None where history.csv's cell is empty.
std::optional<double> estimateOrNone(double error_estimate) {
  if (!std::isfinite(error_estimate)) return std::nullopt;
  return error_estimate;
}

std::string recordText(const IterationRecord& r) {
  const auto optional = [](std::ostream& out, std::optional<double> value) -> std::ostream& {
    if (value) return out << *value;
    return out << "None";
  };
  std::ostringstream text;
  text << "IterationRecord(iteration=" << r.iteration << ", relaxations=" << r.relaxations
       << ", indicator=" << r.indicator << ", error=";
  optional(text, r.error) << ", error_estimate=";
  optional(text, estimateOrNone(r.error_estimate)) << ", rank=" << r.rank << ", wall_s=" << r.wall_s << ")";
  return text.str();
}

py::tuple recordState(const IterationRecord& r) {
  return py::make_tuple(r.iteration, r.relaxations, r.indicator, r.error_estimate, r.error, r.rank, r.sparse_solves,
                        r.wall_s, r.krylov_iterations);
}

IterationRecord recordFromState(const py::tuple& state) {
  if (state.size() != 9) throw std::invalid_argument("a pickled IterationRecord holds 9 values");
  // In the order of stc::IterationRecord's members, as recordState wrote them (the energy, which
  // only the solver's estimate reads, is not kept).
  return {state[0].cast<int>(),
          state[1].cast<int>(),
          state[2].cast<double>(),
          state[3].cast<double>(),
          state[4].cast<std::optional<double>>(),
          state[5].cast<int>(),
          state[6].cast<int>(),
          state[7].cast<double>(),
          std::nullopt,
          state[8].cast<long long>()};
}

void bindRecord(py::module_& module) {
  py::class_<IterationRecord>(module, "IterationRecord", "One iteration of a solve, as history.csv records it.")
      .def_readonly("iteration", &IterationRecord::iteration)
      .def_readonly("relaxations", &IterationRecord::relaxations)
      .def_readonly("indicator", &IterationRecord::indicator)
      .def_readonly("error", &IterationRecord::error)
      .def_property_readonly("error_estimate", [](const IterationRecord& r) { return estimateOrNone(r.error_estimate); })
      .def_readonly("rank", &IterationRecord::rank)
      .def_readonly("sparse_solves", &IterationRecord::sparse_solves)
      .def_readonly("krylov_iterations", &IterationRecord::krylov_iterations)
      .def_readonly("wall_s", &IterationRecord::wall_s)
      .def("__repr__", &recordText)
      .def(py::pickle(&recordState, &recordFromState));
}

void bindProblem(py::module_& module) {
  py::class_<ProblemRef>(module, "Problem", "The assembled problem a result was solved on.")
      .def_property_readonly("n_dofs", [](const ProblemRef& r) { return r.problem()->numDofs(); })
      .def_property_readonly("n_free_dofs", [](const ProblemRef& r) { return r.problem()->numFreeDofs(); })
      .def_property_readonly("n_contact_nodes", [](const ProblemRef& r) { return r.problem()->contact.size(); })
      .def_property_readonly("n_steps", [](const ProblemRef& r) { return r.problem()->numSteps(); })
      .def("displacements", &displacementsFromForces, py::arg("forces"))
      .def("stresses", &stressesOf, py::arg("u"))
      .def(py::pickle([](const ProblemRef& r) { return sceneState(r.scene); },
                      [](const py::tuple& state) { return ProblemRef{sceneFromState(state)}; }));
}

}  // namespace

void bindSolve(py::module_& module) {
  bindRecord(module);
  bindProblem(module);
  module.def(
      "solve",
      [](const SceneHandle& scene, std::optional<std::string> solver, std::optional<double> tol,
         std::optional<int> max_iterations, std::vector<std::string> sets, bool reference,
         std::optional<int> threads, std::optional<std::filesystem::path> out, WarmStart::Matrix forces,
         WarmStart::Matrix displacements, WarmStart::Matrix basis_seed, py::object callback, bool spatial_modes) {
        SolveOptions options{std::move(solver), tol, max_iterations, std::move(sets), reference,
                             threads, std::move(out), spatial_modes};
        return solve(scene, options, {std::move(forces), std::move(displacements), std::move(basis_seed)},
                     std::move(callback));
      },
      py::arg("scene"), py::arg("solver"), py::arg("tol"), py::arg("max_iterations"), py::arg("sets"),
      py::arg("reference"), py::arg("threads"), py::arg("out"), py::arg("start_forces"),
      py::arg("start_displacements"), py::arg("basis_seed"), py::arg("callback"),
      py::arg("spatial_modes"));
}

}  // namespace stc::python
