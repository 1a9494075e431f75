#pragma once
// The PNG plots of `stcontact scaling`, drawn by scripts/plots/scaling.gp from scaling.csv: time to
// the target error and peak memory against m (time series) and against dofs (mesh series).
#include <filesystem>
#include <string>
#include <vector>

#include "stcontact/studies/scaling_study.hpp"

namespace stc {

/// The files the script draws into the report folder: two per series that has sizes.
std::vector<std::string> scalingPlotNames(const ScalingStudy& study);

/// Draws the plots into `dir`. Returns false, with the reason and the command to draw them later in
/// `warning`, when gnuplot is missing or fails.
bool drawScalingPlots(const std::filesystem::path& dir, const ScalingStudy& study, std::string& warning);

}  // namespace stc
