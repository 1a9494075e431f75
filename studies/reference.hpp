#pragma once
// The incremental reference of a solve or a study: the exact solution on the same mesh and grid,
// and the true-error measure on it (src/incremental/error_reference.hpp; docs/method.md §2).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "stcontact/incremental/error_reference.hpp"
#include "stcontact/io/stored_solution.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/options/strategy.hpp"
#include "stcontact/studies/progress.hpp"

namespace stc {

/// `stcontact solve` and the Python module's solve compute no incremental reference (no true error)
/// beyond this many contact nodes unless asked to (ReferenceWish::Always): the reference solve and
/// its per-iteration error evaluation become a noticeable cost.
inline constexpr int kMaxReferenceContactNodes = 1000;

/// What a solve was told about its reference: `--no-reference` (Never), nothing (UpToMaxNodes:
/// kMaxReferenceContactNodes at most), `--reference` (Always, whatever the size).
enum class ReferenceWish { Never, UpToMaxNodes, Always };

/// Whether a solve of `problem` by `strategy` computes the incremental reference: never for the
/// incremental solver itself (it is the reference), else as `wish` says.
bool computesReference(const Problem& problem, Strategy strategy, ReferenceWish wish);

struct ReferenceSolution {
  std::unique_ptr<ErrorReference> reference;
  double solve_s = 0.0;  ///< the incremental solve alone
  double total_s = 0.0;  ///< with the error measure's set-up (its reference energy)
  double factor_nonzeros = 0.0;  ///< entries of the Cholesky factor of K_ff (SpdSolver::factorNonZeros)
};

/// A study's reference: solves `problem` with the incremental solver and builds the true-error
/// measure on it, both with the one factor of K_ff of `operators` (its own when null); throws
/// std::runtime_error when the incremental solve does not converge.
ReferenceSolution computeReference(const Problem& problem, ProgressReporter* progress,
                                   PreparedOperators* operators = nullptr);

/// A solve's reference: the same with the run's `operators`, or nullptr with the reason in
/// `warning` when the incremental solve stops early (the solve then goes on without a true error).
/// `callback` sees the incremental solver's records (progress, Ctrl-C), `note` its phases outside
/// them (SolveInputs::phase_note).
std::unique_ptr<ErrorReference> solveReference(const Problem& problem, const IterationCallback& callback,
                                               std::string& warning, PreparedOperators& operators,
                                               const PhaseNote& note = {});

/// The true error of a run's written solution (src/io/stored_solution.hpp) against the incremental
/// reference: what `stcontact true-error` and the Python module's true_error report.
struct StoredSolutionError {
  StoredSolution stored;
  double error = 0.0;    ///< the relative energy error of its forces
  double seconds = 0.0;  ///< the reference and the measure
};

/// Reads `file` and refuses it unless it was solved on `problem`, whose model is `model_json`
/// (requireSolvedOn: before any cost), then solves the reference as solveReference does (with
/// `operators`, `callback` and `note`) and measures the stored forces against it. None, with the
/// reason in `warning`, when the reference stops early.
std::optional<StoredSolutionError> measureStoredSolution(const Problem& problem, const std::string& model_json,
                                                         const std::filesystem::path& file,
                                                         PreparedOperators& operators,
                                                         const IterationCallback& callback, std::string& warning,
                                                         const PhaseNote& note = {});

}  // namespace stc
