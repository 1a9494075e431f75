#pragma once
// Draws the PNG plots of a report with one of scripts/plots/*.gp (stcontact compare, stcontact
// scaling): gnuplot runs in the report folder, the script writes each NAME.png as NAME.png.tmp
// (variable `suffix`), moved into place once gnuplot succeeded, so a failed run replaces nothing.
#include <filesystem>
#include <string>
#include <vector>

namespace stc::cli {

/// A gnuplot single-quoted string ('' stands for a quote inside).
std::string gnuplotString(const std::string& text);

/// scripts/plots/<name> in the sources.
std::filesystem::path plotScript(const std::string& name);

/// The command that draws the plots later, run from the report folder.
std::string gnuplotCommand(const std::filesystem::path& script, const std::string& variables);

/// Runs `script` with `-e variables` in `dir`, then moves each of `outputs` into place. Returns
/// false, with the reason and the command to draw them later in `warning`, when gnuplot is missing
/// or fails (its output is then in dir/gnuplot.log).
bool drawPlots(const std::filesystem::path& dir, const std::filesystem::path& script, const std::string& variables,
               const std::vector<std::string>& outputs, std::string& warning);

}  // namespace stc::cli
