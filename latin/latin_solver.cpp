#include "stcontact/latin/latin_solver.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "stcontact/latin/global_stage.hpp"
#include "stcontact/latin/indicator.hpp"
#include "stcontact/latin/local_stage.hpp"
#include "stcontact/solver/equilibrium_energy.hpp"
#include "stcontact/solver/error_estimate.hpp"
#include "stcontact/solver/iteration_monitor.hpp"
#include "stcontact/solver/warm_start.hpp"

namespace stc::latin {
namespace {

/// Periods over which the estimate takes its largest ratio of extrapolated error to newest difference
/// when the global stage changes its map (src/solver/error_estimate.hpp; FAS takes 3 for its cycles).
/// With one period, `latin-pgd` on the graded Gmsh half-ball (examples/scenes/half_ball_graded.toml;
/// a direction added every second iteration, the true error falling 2 % per iteration) stopped at
/// true error 1.03e-6 against the tolerance 1e-6; with 3, at 9.9e-7 (docs/hard_cases.md), and 0 to 5
/// more iterations on the example scenes.
constexpr int kChangingMapWindow = 3;

StoppingRule stoppingRuleFor(const LinearStage& global, const LatinOptions& options) {
  StoppingRule rule{options.stop};
  if (global.changesItsMap()) rule.estimate_window = kChangingMapWindow;
  return rule;
}

}  // namespace

SolveResult solveLatin(const Problem& problem, const LatinOptions& options, const SolveInputs& inputs) {
  options.validate();
  SolveInputs clocked = inputs;  // the operator's preparation on the solve's clock
  clocked.origin = inputs.origin.clocked();
  std::unique_ptr<PreparedOperators> own;
  GlobalStage global(problem, operatorsOr(inputs.operators, own), options.block_size);
  return solveLatinWith(problem, global, options, clocked, "latin");
}

SolveResult solveLatinWith(const Problem& problem, LinearStage& global, const LatinOptions& options,
                           const SolveInputs& inputs, const std::string& solver_name) {
  options.validate();
  InterfaceHistory s = startingHistory(problem, inputs);
  requireFits(s, problem);
  const EquilibriumEnergy energy(problem, global.factor());
  IterationMonitor monitor(solver_name, stoppingRuleFor(global, options), &energy, inputs.reference, inputs.callback,
                           inputs.origin);
  const Eigen::VectorXd& k = problem.contact.search_direction;
  const long solves_before = global.sparseSolves();
  InterfaceHistory hat, s_new;
  for (int iteration = 1;; ++iteration) {
    localStage(problem.contact, s, hat);
    global.solve(hat, s_new);
    double gap = 0.0;
    const double eta = indicator(k, s_new, hat, &gap);
    global.observeGap(gap);
    // A convex combination of two iterates in equilibrium is in equilibrium: s stays in A_d. The
    // start is not in this problem's A_d (s = 0 under loads, or a warm start from another problem),
    // so the first iterate is the global stage's own: every later one is then in A_d, as the error
    // estimate's energy products require (src/solver/error_estimate.hpp). Relaxing from the start
    // made the estimate 0 after two iterations at ω ≤ 0.55 (true error 1.1).
    // The relaxed step is ω times the map's own: the estimate judges a fixed point on the latter
    // (ErrorEstimator::record), so that a small ω does not pass for round-off.
    // At a fixed point (IterationMonitor's kFixedPointIndicator) the global stage's iterate is the
    // solution: it is taken whole.
    std::optional<double> unrelaxed_step;
    if (options.relaxation < 1.0 && iteration > 1 && eta > kFixedPointIndicator) {
      unrelaxed_step = std::sqrt(std::max(0.0, energyOfDifference(s_new, s)));
      s.v = options.relaxation * s_new.v + (1.0 - options.relaxation) * s.v;
      s.lambda = options.relaxation * s_new.lambda + (1.0 - options.relaxation) * s.lambda;
    } else {
      std::swap(s, s_new);
    }
    // The controlled stage's projection error bounds the iterate's distance from the exact stage's:
    // ‖δs‖_K ≤ ½ ‖r‖_{k⁻¹} (LinearStage::projectionError).
    if (monitor.record(iteration, eta, s, global.rank(), global.sparseSolves() - solves_before, unrelaxed_step,
                       0.5 * global.projectionError()))
      break;
  }
  return {std::move(s), monitor.finish(), std::move(hat), {}, {}, {}, {}};
}

}  // namespace stc::latin
