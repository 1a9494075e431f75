#pragma once
// The files of a scaling study (docs/scaling.md describes every column):
//   scaling.csv         one row per (series, strategy, size): work to the target, status, memory, sizes
//   summary.md          tables per series, growth exponents, crossover against incremental, memory
//   sizes/<size>/       the comparison report of each size (work_precision.csv, summary.csv, summary.md)
#include <filesystem>
#include <string>

#include "stcontact/studies/scaling_study.hpp"

namespace stc {

std::string scalingCsv(const ScalingStudy& study);
std::string scalingMarkdown(const ScalingStudy& study);

/// "arc_nodes_101_steps_201" (or "divisions_8_steps_201"): the folder of one size's comparison report,
/// below sizes/.
std::string sizeFolderName(const ScalingStudy& study, const ScalingPoint& point);

/// Writes scaling.csv, summary.md and sizes/<size>/ into `dir` (which must exist), each file atomically.
void writeScaling(const std::filesystem::path& dir, const ScalingStudy& study);

}  // namespace stc
