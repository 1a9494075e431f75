// stcontact solve SCENE: choose the solver, compute the incremental reference for the true error
// (scenes small enough, unless --no-reference), solve, write every output file.
#include <iostream>
#include <iomanip>
#include <memory>
#include <sstream>

#include "src/cli/commands.hpp"
#include "src/cli/progress.hpp"
#include "src/core/input_error.hpp"
#include "src/io/atomic_file.hpp"
#include "src/io/run_writer.hpp"
#include "src/scene/scene_reader.hpp"
#include "src/solver/incremental_solver.hpp"
#include "src/strategies/solve_by_name.hpp"

namespace stc::cli {
namespace {

std::unique_ptr<ErrorReference> computeReference(const Problem& problem, bool quiet) {
  Progress progress("reference (incremental)", !quiet);
  std::string warning;
  std::unique_ptr<ErrorReference> reference = solveReference(problem, progress.callback(), warning);
  progress.done();
  if (!warning.empty()) std::cerr << "warning: " << warning << std::endl;
  return reference;
}

SolveResult runSolver(const std::string& name, const Problem& problem, const Scene& scene,
                      const ErrorReference* reference, bool quiet) {
  Progress progress(name, !quiet);
  StrategyInputs inputs;
  inputs.reference = reference;
  inputs.converged_lambda = reference ? &reference->referenceForces() : nullptr;
  inputs.callback = progress.callback();
  inputs.spatial_modes = false;  // not written
  SolveResult result = solveByName(name, problem, scene.solver, inputs);
  progress.done();
  return result;
}

}  // namespace

// A reference that fails (Newton stops at some instant) is not an internal failure: the solve
// goes on without a true error, and the warning says why.
std::unique_ptr<ErrorReference> solveReference(const Problem& problem, const IterationCallback& callback,
                                               std::string& warning) {
  SolveResult ref = solveIncremental(problem, {}, callback);
  if (!ref.summary.converged()) {
    warning = "no true error: the incremental reference did not converge (" + ref.summary.message + ")";
    return nullptr;
  }
  auto factor = std::make_shared<const SpdFactor>(problem.stiffness_free, "K_ff");
  return std::make_unique<ErrorReference>(problem, std::move(factor), std::move(ref.interface.lambda));
}

std::vector<std::string> withSolverOptions(std::vector<std::string> overrides, const std::optional<std::string>& solver,
                                           const std::optional<double>& tolerance,
                                           const std::optional<int>& max_iterations) {
  if (solver) {
    requireAvailable(*solver);
    overrides.push_back("solver.name=" + *solver);
  }
  if (tolerance) {
    if (!(*tolerance > 0.0)) throw InputError("--tol must be > 0");
    std::ostringstream value;
    value << std::setprecision(17) << *tolerance;
    overrides.push_back("solver.tolerance=" + value.str());
  }
  if (max_iterations) {
    if (*max_iterations < 1) throw InputError("--max-iterations must be >= 1");
    overrides.push_back("solver.max_iterations=" + std::to_string(*max_iterations));
  }
  return overrides;
}

int runSolve(const SolveArgs& args) {
  const Scene scene = loadScene(args.scene, withSolverOptions(args.overrides, args.solver, args.tolerance, args.max_iterations));
  const std::string solver = scene.solver.name;
  requireAvailable(solver);
  const std::filesystem::path out = args.out ? std::filesystem::path(*args.out)
                                             : std::filesystem::path("results") / scene.name / solver;
  const Problem problem = buildProblem(scene);  // bad input stops here, before anything is created
  ensureWritableDirectory(out);                  // fail before the solve, not after

  std::unique_ptr<ErrorReference> reference;
  if (solver != "incremental" && !args.no_reference && problem.contact.size() <= kMaxReferenceContactNodes)
    reference = computeReference(problem, args.quiet);
  const SolveResult result = runSolver(solver, problem, scene, reference.get(), args.quiet);
  writeRunOutputs(out, problem, result, {scene.parameters_json, STC_VERSION}, scene.output);

  if (!args.quiet) {
    const auto& s = result.summary;
    std::cout << solver << ": " << toString(s.termination) << " — " << s.message << "\n"
              << "  iterations " << s.iterations << ", indicator " << s.indicator;
    if (s.error) std::cout << ", true error " << *s.error;
    std::cout << ", " << s.wall_s << " s\n  results in " << out.string() << "/\n";
  }
  return result.summary.converged() ? 0 : 2;
}

}  // namespace stc::cli
