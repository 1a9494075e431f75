#pragma once
// Writes every output file of a solved run into one folder (docs/interface.md "Output files"), each
// atomically (temporary file, then rename): reactions.csv, contact.csv, history.csv,
// summary.json, and solution.pvd + vtu/ when asked.
#include <filesystem>
#include <string>
#include <vector>

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
};

/// The frames take K_ff from `operators` (the run's: prepared once, shared with its reference and
/// its solve), and summary.json lists what the run prepared.
void writeRunOutputs(const std::filesystem::path& dir, const Problem& problem, const SolveResult& result,
                     const RunInfo& info, const OutputSpec& output, PreparedOperators& operators);

/// history.csv: iteration,relaxations,indicator,error,rank,wall_s (error empty when unknown).
std::string historyCsv(const SolveSummary& summary);
/// summary.json, with the operators the run prepared.
std::string summaryJson(const Problem& problem, const SolveSummary& summary, const RunInfo& info,
                        const std::vector<Preparation>& preparations);

/// solution.pvd + vtu/step_XXXXX.vtu: displacement, contact force and state (nodes), stress tensor
/// and von Mises stress (elements) at every `stride`-th instant and the last one.
void writeSolutionSeries(const std::filesystem::path& dir, const Problem& problem, const SolveResult& result,
                         int stride, VtuPrecision precision, PreparedOperators& operators);

}  // namespace stc
