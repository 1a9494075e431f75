#include "stcontact/studies/reference.hpp"

#include <chrono>
#include <stdexcept>

#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/linalg/spd_solver.hpp"

namespace stc {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

ReferenceSolution computeReference(const Problem& problem, ProgressReporter* progress, PreparedOperators* operators) {
  std::unique_ptr<PreparedOperators> own;
  PreparedOperators& prepared = operatorsOr(operators, own);
  ReferenceSolution out;
  const auto start = Clock::now();
  SolveResult ref;
  {
    const RunProgress run(progress, "reference (incremental)");
    ref = solveIncremental(problem, {}, {.callback = run.callback(), .operators = &prepared});
  }
  out.solve_s = secondsSince(start);
  if (!ref.summary.converged())
    throw std::runtime_error("the incremental reference did not converge: " + ref.summary.message);
  std::shared_ptr<const SpdSolver> factor = prepared.stiffnessFree(problem);
  out.factor_nonzeros = factor->factorNonZeros();
  out.reference = std::make_unique<ErrorReference>(problem, std::move(factor), std::move(ref.interface.lambda));
  out.total_s = secondsSince(start);
  return out;
}

bool computesReference(const Problem& problem, Strategy strategy, ReferenceWish wish) {
  if (strategy == Strategy::Incremental || wish == ReferenceWish::Never) return false;
  return wish == ReferenceWish::Always || problem.contact.size() <= kMaxReferenceContactNodes;
}

// A reference that fails (Newton stops at some instant) is not an internal failure: the solve
// goes on without a true error, and the warning says why.
std::unique_ptr<ErrorReference> solveReference(const Problem& problem, const IterationCallback& callback,
                                               std::string& warning, PreparedOperators& operators,
                                               const PhaseNote& note) {
  try {
    SolveResult ref =
        solveIncremental(problem, {}, {.callback = callback, .operators = &operators, .phase_note = note});
    if (!ref.summary.converged()) {
      warning = "no true error: the incremental reference did not converge (" + ref.summary.message + ")";
      return nullptr;
    }
    return std::make_unique<ErrorReference>(problem, operators.stiffnessFree(problem), std::move(ref.interface.lambda));
  } catch (const LinearSolveFailure& failure) {  // an iterative backend that did not reach its tolerance
    warning = std::string("no true error: the incremental reference's linear solve failed (") + failure.what() + ")";
    return nullptr;
  }
}

std::optional<StoredSolutionError> measureStoredSolution(const Problem& problem, const std::string& model_json,
                                                         const std::filesystem::path& file,
                                                         PreparedOperators& operators,
                                                         const IterationCallback& callback, std::string& warning,
                                                         const PhaseNote& note) {
  StoredSolutionError out{readStoredSolution(file)};
  requireSolvedOn(out.stored, problem, model_json);
  const auto start = Clock::now();
  const std::unique_ptr<ErrorReference> reference = solveReference(problem, callback, warning, operators, note);
  if (!reference) return std::nullopt;
  out.error = reference->relativeError(out.stored.lambda);
  out.seconds = secondsSince(start);
  return out;
}

}  // namespace stc
