#pragma once
// Sub-commands of the stcontact program (docs/interface.md "Command line").
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "src/problem/problem.hpp"
#include "src/scene/scene.hpp"
#include "src/solver/error_reference.hpp"
#include "src/solver/solve_summary.hpp"

namespace stc::cli {

struct CheckArgs {
  std::string scene;
  std::vector<std::string> overrides;
};

struct SolveArgs {
  std::string scene;
  std::optional<std::string> solver;
  std::optional<std::string> out;
  std::optional<double> tolerance;
  std::optional<int> max_iterations;
  std::vector<std::string> overrides;
  bool quiet = false;
  bool no_reference = false;
};

struct SvdArgs {
  std::string scene;
  std::vector<std::string> overrides;
  std::optional<std::string> out;
  int modes = 10;                       ///< pairs written to the per-mode files and tables
  std::string solver = "incremental";   ///< the only one accepted: the analysis of the exact solution
};

/// readScene (src/scene/scene_reader.hpp), then each of the scene's warnings (deprecated keys) on
/// standard error as "warning: FILE: MESSAGE", once per message and run.
Scene loadScene(const std::string& file, const std::vector<std::string>& overrides);

/// `stcontact solve` computes no incremental reference (no true error) beyond this many contact
/// nodes: the reference solve and its per-iteration error evaluation become a noticeable cost.
/// The Python module's solve follows the same rule.
inline constexpr int kMaxReferenceContactNodes = 1000;

/// The true-error reference of `solve`: the incremental solution and the error measure on it; nullptr,
/// with the reason in `warning`, when the incremental solve stops early (the solve then goes on
/// without a true error). `callback` sees the incremental solver's records (progress, Ctrl-C).
std::unique_ptr<ErrorReference> solveReference(const Problem& problem, const IterationCallback& callback,
                                               std::string& warning);

/// `overrides` followed by --solver, --tol and --max-iterations as scene overrides (each checked:
/// a known solver, tol > 0, max-iterations >= 1), so that a scene's parameters say what was solved.
std::vector<std::string> withSolverOptions(std::vector<std::string> overrides, const std::optional<std::string>& solver,
                                           const std::optional<double>& tolerance,
                                           const std::optional<int>& max_iterations = std::nullopt);

/// Prints the model's sizes; returns the exit status.
int runCheck(const CheckArgs& args);
/// Solves and writes the outputs; returns 0 converged, 2 not converged.
int runSolve(const SolveArgs& args);
/// A posteriori space-time SVD of the incremental solution (docs/method.md §3); returns 0, or 2 if the
/// solve did not converge (nothing written).
int runSvd(const SvdArgs& args);

}  // namespace stc::cli
