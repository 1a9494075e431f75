#include "stcontact/studies/scaling_plots.hpp"

#include <algorithm>

#include "stcontact/studies/gnuplot_runner.hpp"
#include "stcontact/studies/number_format.hpp"

namespace stc {

namespace {

/// The incremental solver's forms over the study's solves at tolerance, in the order met, e.g.
/// "interface, whole-body" (`auto` chooses per size): the legend of its line.
std::string incrementalForms(const ScalingStudy& study) {
  std::vector<std::string> forms;
  for (const ScalingPoint& p : study.points)
    if (const StrategyMeasurement* m = p.strategy("incremental"); m && m->at_tolerance) {
      const std::string& form = m->at_tolerance->incremental_form;
      if (!form.empty() && std::find(forms.begin(), forms.end(), form) == forms.end()) forms.push_back(form);
    }
  std::string text;
  for (const std::string& form : forms) text += (text.empty() ? "" : ", ") + form;
  return text;
}

/// The series that have sizes, as the script names them.
std::string seriesWithSizes(const ScalingStudy& study) {
  std::string series;
  if (!seriesPoints(study, Series::Time).empty()) series = "time";
  if (!seriesPoints(study, Series::Mesh).empty()) series += series.empty() ? "mesh" : " mesh";
  return series;
}

}  // namespace

std::vector<std::string> scalingPlotNames(const ScalingStudy& study) {
  std::vector<std::string> names;
  if (!seriesPoints(study, Series::Time).empty()) names = {"time_vs_steps.png", "memory_vs_steps.png"};
  if (!seriesPoints(study, Series::Mesh).empty()) {
    names.push_back("time_vs_dofs.png");
    names.push_back("memory_vs_dofs.png");
  }
  return names;
}

bool drawScalingPlots(const std::filesystem::path& dir, const ScalingStudy& study, std::string& warning) {
  std::string solvers;
  for (const auto& s : study.solvers) solvers += (solvers.empty() ? "" : " ") + s;
  const std::string variables = "solvers=" + gnuplotString(solvers) + "; target=" +
                                gnuplotString(targetLabel(study.target_error)) + "; scene=" +
                                gnuplotString(study.scene_name) + "; series=" + gnuplotString(seriesWithSizes(study)) +
                                (study.first_reach ? "" : "; timecol='time_at_tolerance_s'") +
                                "; incremental_forms=" + gnuplotString(incrementalForms(study));
  return drawPlots(dir, reportPlotJob("scaling.gp", variables, scalingPlotNames(study)), warning);
}

}  // namespace stc
