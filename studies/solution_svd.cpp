#include "stcontact/studies/solution_svd.hpp"

#include <algorithm>
#include <chrono>
#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/operators/displacement.hpp"

namespace stc {

void checkSvdSizes(int instants, int modes) {
  if (instants < 3) throw InputError("svd needs at least 3 instants (time.steps = " + std::to_string(instants) + ")");
  if (modes < 1 || modes > instants - 1)
    throw InputError("--modes = " + std::to_string(modes) + " must be in [1, " + std::to_string(instants - 1) +
                     "] (time.steps - 1)");
}

SolutionHistory incrementalHistory(const Problem& problem, const IterationCallback& callback) {
  PreparedOperators operators;
  SolutionHistory out;
  const auto start = std::chrono::steady_clock::now();
  out.solved = solveIncremental(problem, {}, {.callback = callback, .operators = &operators});
  out.solve_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (out.solved.summary.converged())
    out.U = fullDisplacements(problem, *operators.stiffnessFree(problem), out.solved.interface.lambda);
  return out;
}

pgd::SpaceTimeSvd arpackEnergySvd(const Eigen::MatrixXd& U, const Eigen::SparseMatrix<double>& K, int modes) {
  pgd::EnergySvdOptions options;
  options.method = pgd::SvdMethod::Arpack;
  options.modes = std::min(static_cast<int>(U.cols()) - 1, std::max(modes, kSvdFigurePairs));
  return pgd::energySvd(U, K, options);
}

}  // namespace stc
