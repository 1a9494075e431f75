#pragma once
// The PNG plots of `stcontact compare`, drawn by scripts/plots/work_precision.gp from
// work_precision.csv: true error against wall time, relaxations and sparse solves.
#include <filesystem>
#include <string>
#include <vector>

#include "stcontact/studies/comparison.hpp"

namespace stc {

/// The files the script draws into the report folder.
const std::vector<std::string>& workPrecisionPlotNames();

/// The gnuplot command that (re)draws the plots of `comparison`, run from its report folder.
std::string workPrecisionPlotCommand(const Comparison& comparison);

/// Draws the plots into `dir` (each PNG moved into place once complete). Returns false, with the
/// reason and the command to draw them later in `warning`, when gnuplot is missing or fails.
bool drawWorkPrecisionPlots(const std::filesystem::path& dir, const Comparison& comparison, std::string& warning);

}  // namespace stc
