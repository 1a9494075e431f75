#pragma once
// The one way the program and its studies draw PNG plots: a gnuplot script run in the report
// folder. The script writes NAME.png<suffix> (suffix='.tmp' is passed with -e); each is moved into
// place once gnuplot has succeeded, so a failed run never leaves a half picture. Without gnuplot the
// data and the script are still there, and plotCommand() says how to draw the plots later.
#include <filesystem>
#include <string>
#include <vector>

namespace stc {

struct PlotJob {
  std::filesystem::path script;      ///< the gnuplot script; a relative path is read in the report folder
  std::string variables;             ///< gnuplot -e text (without `suffix`), e.g. "scene='seed'"; may be empty
  std::vector<std::string> outputs;  ///< the PNG names the script draws
  /// gnuplot's output into gnuplot.log in the folder (removed after a success, kept for a failure);
  /// false: into the program's own stdout and stderr.
  bool log = true;
};

enum class PlotStatus {
  Drawn,           ///< every PNG written and moved into place
  GnuplotMissing,  ///< no `gnuplot` on PATH: nothing drawn
  ScriptMissing,   ///< the script is not there: nothing drawn
  GnuplotFailed,   ///< gnuplot ran and failed (`exit_status`): no PNG replaced
  NotMoved,        ///< a finished PNG could not be renamed into place (`detail` says which and why)
};

struct PlotOutcome {
  PlotStatus status = PlotStatus::Drawn;
  int exit_status = 0;  ///< gnuplot's, for GnuplotFailed (127: could not be started, −1: killed)
  std::string detail;   ///< for NotMoved: "could not move X into place: reason"
};

/// A gnuplot single-quoted string ('' stands for a quote inside).
std::string gnuplotString(const std::string& text);

/// The command that (re)draws the plots, run from the report folder.
std::string plotCommand(const PlotJob& job);

/// Runs `gnuplot -e "<variables>; suffix='.tmp'" <script>` in `dir` (fork, chdir, exec), then renames
/// each <name>.tmp to <name>; the temporaries of a failed run are removed.
PlotOutcome runPlots(const std::filesystem::path& dir, const PlotJob& job);

/// runPlots with the reports' wording (`compare`, `sweep`, `scaling`): returns false, with the reason
/// and the command to draw the plots later in `warning`, when gnuplot is missing or fails.
bool drawPlots(const std::filesystem::path& dir, const PlotJob& job, std::string& warning);

/// The job of a report's `script`, a file name in scripts/plots/ (e.g. "work_precision.gp"), with the
/// gnuplot -e text `variables` (without `suffix`) and the PNG names it draws.
PlotJob reportPlotJob(const std::string& script, std::string variables, std::vector<std::string> outputs);

}  // namespace stc
