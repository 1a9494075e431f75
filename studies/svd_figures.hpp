#pragma once
// The pictures of `stcontact svd`, after the seed paper's Figs. 2 and 3 (§3.1): a gnuplot script
// written next to the data files it reads (singular_values.csv, time_functions.csv,
// modes_deformed.dat; see svd_tables.hpp), and the program that runs it. The script can be rerun
// by hand in its folder (`gnuplot svd_figures.gp`); the program passes suffix='.tmp' and renames the
// finished PNGs into place, so that each picture appears atomically, as every other output file.
#include <filesystem>
#include <string>
#include <vector>

namespace stc {

struct SvdFigureSpec {
  std::string scene;                 ///< for the titles
  int singular_values = 50;          ///< σ_i shown in singular_values.png (seed Fig. 3a: 50)
  int time_functions = 6;            ///< curves in time_functions.png (seed Fig. 3b: 6)
  std::vector<double> mode_scales;   ///< s_i of the deformed shapes in modes.png (seed Fig. 2: 6 modes)
  std::vector<double> mode_energy;   ///< σ_i² / ‖U‖²_K of those modes, for the panel titles
};

/// The script text. Outputs: singular_values.png, time_functions.png, modes.png (each name followed
/// by the gnuplot variable `suffix`, empty unless given with -e).
std::string svdFiguresScript(const SvdFigureSpec& spec);

enum class FigureStatus {
  Drawn,           ///< every PNG written
  GnuplotMissing,  ///< no `gnuplot` on PATH: nothing drawn
  GnuplotFailed,   ///< gnuplot ran and failed: no PNG replaced; `detail` says how
};

/// Runs `gnuplot -e "suffix='.tmp'" svd_figures.gp` in `dir` (runPlots, gnuplot_runner.hpp), then renames
/// each <name>.png.tmp to <name>.png; temporaries of a failed run are removed. `detail` receives
/// a one-line explanation when the status is not Drawn.
FigureStatus drawSvdFigures(const std::filesystem::path& dir, std::string& detail);

/// The PNGs drawSvdFigures writes.
const std::vector<std::string>& svdFigureNames();

}  // namespace stc
