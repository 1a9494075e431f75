#include "stcontact/studies/compare_plots.hpp"

#include "stcontact/studies/gnuplot_runner.hpp"

namespace stc {
namespace {

/// The -e argument: which strategies are curves (with the repeat drawn), which one is the point.
std::string scriptVariables(const Comparison& c) {
  std::string curves, repeats, reference;
  for (const StrategyMeasurement& m : c.strategies) {
    if (m.reference_point) {
      reference = m.solver;
      continue;
    }
    if (!curves.empty()) {
      curves += ' ';
      repeats += ' ';
    }
    curves += m.solver;
    repeats += std::to_string(summarize(m).median_repeat);
  }
  return "curves=" + gnuplotString(curves) + "; repeats=" + gnuplotString(repeats) +
         "; reference=" + gnuplotString(reference) + "; scene=" + gnuplotString(c.scene_name);
}

PlotJob workPrecisionJob(const Comparison& c) {
  return reportPlotJob("work_precision.gp", scriptVariables(c), workPrecisionPlotNames());
}

}  // namespace

const std::vector<std::string>& workPrecisionPlotNames() {
  static const std::vector<std::string> names = {"error_vs_time.png", "error_vs_relaxations.png",
                                                 "error_vs_sparse_solves.png"};
  return names;
}

std::string workPrecisionPlotCommand(const Comparison& c) { return plotCommand(workPrecisionJob(c)); }

bool drawWorkPrecisionPlots(const std::filesystem::path& dir, const Comparison& c, std::string& warning) {
  return drawPlots(dir, workPrecisionJob(c), warning);
}

}  // namespace stc
