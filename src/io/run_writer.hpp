#pragma once
// Writes every output file of a solved run into one folder (docs/interface.md "Output files"), each
// atomically (temporary file, then rename): reactions.csv, history.csv, solution.h5 (+ solution.xdmf
// with its frames), contact.csv when small or asked, solution.pvd + vtu/ when asked, summary.json last.
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "stcontact/io/solution_file.hpp"
#include "stcontact/operators/prepared_operators.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/output_spec.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc {

struct RunInfo {
  std::string parameters_json = "{}";  ///< the scene as read (Scene::parameters_json)
  std::string version;                 ///< stcontact version, recorded in summary.json
  /// Each rank's peak resident size in bytes (valuesOfEveryRank(peakResidentBytes()) after the
  /// solve, made by every rank); the writing rank's is read again when summary.json is written
  /// (empty: one process, read then).
  std::vector<double> peak_memory_bytes;
  /// When the run began (the front end's clock), for summary.json's run_s; none: not recorded.
  std::optional<std::chrono::steady_clock::time_point> started;
  /// The seconds the true error's reference took (summary.json's reference_s), none without one.
  std::optional<double> reference_s;
  std::string model_json = "{}";  ///< the model alone (Scene::model_json), solution.h5's "model"
};

/// The frames come from the displacement the strategy holds (SolveResult::displacement) or, for a
/// strategy that holds none, from λ with K_ff taken from `operators` (the run's: prepared once,
/// shared with its reference and its solve); summary.json lists what the run prepared and counts the
/// writer's solves.
void writeRunOutputs(const std::filesystem::path& dir, const Problem& problem, const SolveResult& result,
                     const RunInfo& info, const OutputSpec& output, PreparedOperators& operators);

/// history.csv: iteration,relaxations,indicator,error,rank,wall_s,error_estimate,sparse_solves,
/// krylov_iterations (error and estimate empty when unknown).
std::string historyCsv(const SolveSummary& summary);
/// What writing a run folder took: the writer's sparse solves (VTU frames solved from λ) and its
/// seconds before summary.json.
struct WriterCounts {
  long sparse_solves = 0;
  double seconds = 0.0;
};

/// summary.json, with the operators the run prepared and what its writer took.
std::string summaryJson(const Problem& problem, const SolveSummary& summary, const RunInfo& info,
                        const std::vector<Preparation>& preparations, const WriterCounts& writer = {});

/// solution.pvd + vtu/step_XXXXX.vtu: displacement, contact force and state (nodes), stress tensor
/// and von Mises stress (elements) at every `stride`-th instant (0: io/frame_fields.hpp's
/// autoFrameStride) and the last one. The displacement is result.displacement's where held (no
/// factor, no solve), else solved from λ. Returns the sparse solves made (one per frame, or none).
long writeSolutionSeries(const std::filesystem::path& dir, const Problem& problem, const SolveResult& result,
                         int stride, FieldPrecision precision, PreparedOperators& operators);

/// solution.h5 (io/solution_file.hpp), with its frames and solution.xdmf when `frames`; returns the
/// sparse solves its frames made (none when the strategy holds its displacement).
long writeSolutionFile(const std::filesystem::path& dir, const Problem& problem, const SolveResult& result,
                       const RunTables& tables, const RunInfo& info, const OutputSpec& output, bool frames,
                       PreparedOperators& operators);

/// Whether the run writes contact.csv (output.contact_csv; "auto": when it stays small).
bool writesContactCsv(const Problem& problem, const OutputSpec& output);

}  // namespace stc
