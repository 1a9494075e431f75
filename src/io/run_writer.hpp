#pragma once
// Writes every output file of a solved run into one folder (docs/interface.md "Output files"), each
// atomically (temporary file, then rename): reactions.csv, contact.csv, history.csv,
// summary.json, and solution.pvd + vtu/ when asked.
#include <filesystem>
#include <string>

#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc {

struct RunInfo {
  std::string parameters_json = "{}";  ///< the scene as read (Scene::parameters_json)
  std::string version;                 ///< stcontact version, recorded in summary.json
};

void writeRunOutputs(const std::filesystem::path& dir, const Problem& problem, const SolveResult& result,
                     const RunInfo& info, const OutputSpec& output);

/// history.csv: iteration,relaxations,indicator,error,rank,wall_s (error empty when unknown).
std::string historyCsv(const SolveSummary& summary);
/// summary.json.
std::string summaryJson(const Problem& problem, const SolveSummary& summary, const RunInfo& info);

/// solution.pvd + vtu/step_XXXXX.vtu: displacement, contact force and state (nodes), stress tensor
/// and von Mises stress (elements) at every `stride`-th instant and the last one.
void writeSolutionSeries(const std::filesystem::path& dir, const Problem& problem, const SolveResult& result,
                         int stride, VtuPrecision precision = VtuPrecision::Float32);

}  // namespace stc
