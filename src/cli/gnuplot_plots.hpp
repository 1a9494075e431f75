#pragma once
// PNG plots of the reports (`compare`, `sweep`), drawn by a gnuplot script of scripts/plots/ run in
// the report folder. The script writes NAME.png<suffix>; each is moved into place once gnuplot has
// succeeded, so a failed run never leaves a half picture. Without gnuplot the report is still
// written and the warning gives the command that draws the plots later.
#include <filesystem>
#include <string>
#include <vector>

namespace stc::cli {

struct PlotJob {
  std::string script;                ///< file name in scripts/plots/, e.g. "work_precision.gp"
  std::string variables;             ///< gnuplot -e text (without `suffix`), e.g. "scene='seed'"
  std::vector<std::string> outputs;  ///< the PNG names the script draws
};

/// A gnuplot single-quoted string ('' stands for a quote inside).
std::string gnuplotString(const std::string& text);

/// The command that (re)draws the plots, run from the report folder.
std::string plotCommand(const PlotJob& job);

/// Draws the plots into `dir`. Returns false, with the reason and the command to draw them later in
/// `warning`, when gnuplot is missing or fails.
bool drawPlots(const std::filesystem::path& dir, const PlotJob& job, std::string& warning);

}  // namespace stc::cli
