#pragma once
// PNG plots of the reports (`compare`, `sweep`, `scaling`): a gnuplot script of scripts/plots/, run in
// the report folder by the one gnuplot runner (src/report/gnuplot_runner.hpp).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "src/report/gnuplot_runner.hpp"

namespace stc::cli {

/// The job of `script`, a file name in scripts/plots/ (e.g. "work_precision.gp"), with the gnuplot
/// -e text `variables` (without `suffix`) and the PNG names it draws.
inline PlotJob reportPlotJob(const std::string& script, std::string variables, std::vector<std::string> outputs) {
  return {std::filesystem::path(STC_PLOT_SCRIPTS) / script, std::move(variables), std::move(outputs)};
}

}  // namespace stc::cli
