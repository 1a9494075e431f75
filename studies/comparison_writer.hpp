#pragma once
// The files of a comparison report (docs/compare.md describes every column):
//   work_precision.csv  one row per recorded iteration of every timed run
//   summary.csv         one row per strategy: medians of the work to reach 1e-2, 1e-4, 1e-6, ratios, memory
//   summary.md          the same for a reader, with the machine, the build and how it was measured
#include <filesystem>
#include <string>

#include "stcontact/studies/comparison.hpp"

namespace stc {

std::string workPrecisionCsv(const Comparison& comparison);
std::string summaryCsv(const Comparison& comparison);
std::string summaryMarkdown(const Comparison& comparison);

/// Writes the three files into `dir` (which must exist), each atomically.
void writeComparison(const std::filesystem::path& dir, const Comparison& comparison);

}  // namespace stc
