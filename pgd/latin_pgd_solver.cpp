#include "stcontact/pgd/latin_pgd_solver.hpp"

#include "stcontact/latin/latin_solver.hpp"
#include "stcontact/pgd/separated_history.hpp"

namespace stc::pgd {

SolveResult solveLatinPgd(const Problem& problem, const LatinPgdOptions& options, const InterfaceHistory* start,
                          const Eigen::MatrixXd* seed, const ErrorReference* reference,
                          const IterationCallback& callback) {
  options.validate();
  ControlledGlobalStage stage(problem, options.stage);
  if (seed) stage.seed(*seed);
  const InterfaceHistory zero = InterfaceHistory::zeros(problem.contact, problem.numSteps());
  SolveResult result =
      latin::solveLatin(problem, stage, start ? *start : zero, options.latin, reference, callback, "latin-pgd");
  result.interface_directions = stage.basis().directions();
  if (options.spatial_modes) result.spatial_modes = energyModes(stage.basis(), stage.coordinates());
  return result;
}

}  // namespace stc::pgd
