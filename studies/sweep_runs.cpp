#include "stcontact/studies/sweep_runs.hpp"

#include <chrono>

#include "stcontact/io/atomic_file.hpp"
#include "stcontact/io/run_writer.hpp"
#include "stcontact/solver/warm_start.hpp"
#include "stcontact/strategies/registry.hpp"
#include "stcontact/studies/number_format.hpp"
#include "stcontact/studies/reference.hpp"
#include "stcontact/version.hpp"

namespace stc {
namespace {

using Clock = std::chrono::steady_clock;

struct TimedSolve {
  SolveResult result;
  SolveCost cost;
};

/// One solve through the registry (strategies/registry.hpp), timed from the call to its return (set-up included), its true
/// error measured afterwards on the returned solution (the solve itself does not pay for it).
TimedSolve timedSolve(const Problem& problem, const Scene& scene, const SolveInputs& base,
                      const ReferenceSolution& reference, const std::string& label, const SweepSettings& settings) {
  SolveInputs inputs = base;
  inputs.converged_lambda = &reference.reference->referenceForces();  // fas-aposteriori's modes, not timed
  inputs.spatial_modes = false;  // the next point starts from the interface directions
  const auto start = Clock::now();
  TimedSolve out;
  {
    const RunProgress progress(settings.progress, label);
    inputs.callback = progress.callback();
    inputs.phase_note = progress.phaseNote();
    out.result = solve(settings.solver, problem, scene.solver, inputs);
  }
  out.cost = costOf(out.result.summary, std::chrono::duration<double>(Clock::now() - start).count());
  out.cost.error = reference.reference->relativeError(out.result.interface.lambda);
  return out;
}

std::string costLine(const SolveCost& c) {
  std::string line = std::string(toString(c.termination)) + ", " + std::to_string(c.relaxations) + " relaxations, " +
                     shortNumber(c.wall_s, 3) + " s";
  if (c.error) line += ", true error " + shortNumber(*c.error, 2);
  return line;
}

std::string pointLine(const SweepPoint& p, const std::string& key) {
  std::string line = "  " + key + "=" + p.text + ": warm (from " + toString(p.start) + ") " + costLine(p.warm);
  if (p.cold) line += "; cold " + costLine(*p.cold);
  return line;
}

// The frames take K_ff from the point's reference (`operators`); the timed solves prepare their own.
void writeSolution(const std::filesystem::path& dir, const Problem& problem, const Scene& scene,
                   const SolveResult& result, PreparedOperators& operators) {
  ensureWritableDirectory(dir);
  writeRunOutputs(dir, problem, result, {scene.parameters_json, STC_VERSION, {}, {}, {}, scene.model_json},
                  scene.output, operators);
}

}  // namespace

SweepPoint WarmChain::solveValue(const Scene& scene, const SweepRange& range, std::size_t index,
                                 const SweepSettings& settings) {
  const Problem problem = buildProblem(scene);  // K + BᵀkB and its factor may depend on the value
  PreparedOperators operators(scene.solver.linearAtTolerance());
  const ReferenceSolution reference = computeReference(problem, settings.progress, &operators);
  const std::string label = range.override(index) + " (" + std::to_string(index + 1) + "/" +
                            std::to_string(range.values.size()) + ") ";
  SweepPoint point;
  point.text = range.texts[index];
  point.value = range.values[index];
  point.reference_s = reference.total_s;

  SolveInputs warm;
  if (interface_ && fitsProblem(*interface_, problem)) {
    warm.start = &*interface_;
    point.start = WarmStart::Previous;
    if (modes_.cols() > 0 && fitsProblem(modes_, problem)) {
      warm.basis_seed = &modes_;
      point.seed_modes = static_cast<int>(modes_.cols());
    }
  }
  TimedSolve solved = timedSolve(problem, scene, warm, reference, label + "warm", settings);
  point.warm = solved.cost;
  point.forces = endForces(problem.contact, solved.result.interface);
  if (settings.independent) point.cold = timedSolve(problem, scene, {}, reference, label + "cold", settings).cost;
  if (settings.solutions_dir)
    writeSolution(*settings.solutions_dir / ("value_" + point.text), problem, scene, solved.result, operators);
  if (settings.progress) settings.progress->note(pointLine(point, range.key));

  interface_ = std::move(solved.result.interface);
  modes_ = std::move(solved.result.interface_directions);
  return point;
}

}  // namespace stc
