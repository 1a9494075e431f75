#include "stcontact/studies/svd_figures.hpp"

#include <cstdio>
#include <sstream>

#include "stcontact/studies/gnuplot_runner.hpp"

namespace stc {
namespace {

// A gnuplot double-quoted string: backslash and quote escaped, so that any scene name is safe.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// Seed Fig. 3a: σ_i on a log scale (left axis), cumulative energy in % (right axis, linear).
void singularValuesPlot(std::ostream& gp, const SvdFigureSpec& spec) {
  gp << "set output 'singular_values.png'.suffix\n"
     << "set title " << quoted(spec.scene + ": singular values in the energy product, cumulative elastic energy") << "\n"
     << "set xlabel 'pair i'\nset ylabel 'sigma_i'\nset logscale y\nset format y '1e%T'\n"
     << "set y2label 'cumulative energy (%)'\nset y2tics\nset ytics nomirror\nset y2range [*:100]\n"
     << "set key center right\n"
     << "plot 'singular_values.csv' every ::0::" << spec.singular_values - 1
     << " using 1:2 axes x1y1 with linespoints pt 7 ps 0.7 lw 2 title 'sigma_i', \\\n"
     << "     '' every ::0::" << spec.singular_values - 1
     << " using 1:(100*$4) axes x1y2 with linespoints pt 6 ps 0.7 lw 2 title 'cumulative energy (%)'\n"
     << "unset logscale y\nset format y '%g'\nunset y2tics\nunset y2label\nset ytics mirror\n\n";
}

// Seed Fig. 3b: the first time functions ν_i √σ_i.
void timeFunctionsPlot(std::ostream& gp, const SvdFigureSpec& spec) {
  gp << "set output 'time_functions.png'.suffix\n"
     << "set title " << quoted(spec.scene + ": time functions nu_i(t) sqrt(sigma_i)") << "\n"
     << "set xlabel 't'\nset ylabel 'nu_i sqrt(sigma_i)'\nset key outside right\n"
     << "plot for [i=2:" << spec.time_functions + 1
     << "] 'time_functions.csv' using 1:i with lines lw 2 title columnhead(i)\n\n";
}

// Seed Fig. 2: deformed meshes x + s_i Υ_i √σ_i, triangles coloured by the mode's energy density
// relative to its mean (log scale), 2 × 3 panels.
void modesPlot(std::ostream& gp, const SvdFigureSpec& spec) {
  const int modes = static_cast<int>(spec.mode_scales.size());
  const int columns = modes < 3 ? modes : 3, rows = (modes + columns - 1) / columns;
  // libgd's png keeps this picture of ~6000 filled triangles small (65 kB against 380 kB with
  // pngcairo's antialiasing); pngcairo only where gnuplot was built without libgd.
  gp << "modes_terminal = strstrt(GPVAL_TERMINALS, ' png ') > 0 ? 'png' : 'pngcairo'\n"
     << "set terminal @modes_terminal size " << 400 * columns + 100 << "," << 300 * rows + 60
     << " font ',10' noenhanced\n"
     << "set output 'modes.png'.suffix\n"
     << "set datafile separator whitespace\nset datafile nocolumnheaders\n"
     << "set multiplot layout " << rows << "," << columns << " title "
     << quoted(spec.scene + ": spatial modes Upsilon_i sqrt(sigma_i), deformed (scale s), coloured by energy "
                            "density / mean density (log)")
     << "\n"
     << "unset key\nunset tics\nunset border\nunset xlabel\nunset ylabel\nset size ratio -1\n"
     << "set xrange [-1.25:1.25]\nset yrange [-1.25:0.25]\n"
     << "set style fill solid 1.0 noborder\nset logscale cb\nset cbrange [1e-2:1e2]\n"
     << "set cbtics ('0.01' 0.01, '0.1' 0.1, '1' 1, '10' 10, '100' 100)\n"
     << "set palette defined (0 '#f2f2f2', 1 '#c6dbef', 2 '#4292c6', 3 '#08306b', 4 '#000000')\n";
  for (int i = 0; i < modes; ++i) {
    char title[160];
    std::snprintf(title, sizeof title, "mode %d: %.3g %% of the energy, s = %.3g", i + 1, 100.0 * spec.mode_energy[i],
                  spec.mode_scales[i]);
    gp << ((i + 1) % columns == 0 || i + 1 == modes ? "set colorbox\n" : "unset colorbox\n") << "set title "
       << quoted(title) << "\n"
       << "plot 'modes_deformed.dat' index " << i << " using 1:2:3 with polygons fc palette, \\\n"
       << "     '' index " << i << " using 1:2 with lines lc rgb '#909090' lw 0.4\n";
  }
  gp << "unset multiplot\n";
}

}  // namespace

const std::vector<std::string>& svdFigureNames() {
  static const std::vector<std::string> names = {"singular_values.png", "time_functions.png", "modes.png"};
  return names;
}

std::string svdFiguresScript(const SvdFigureSpec& spec) {
  std::ostringstream gp;
  gp << "# Figures of `stcontact svd` after the seed paper's Figs. 2 and 3 (CSMA 2013, §3.1).\n"
     << "# Rerun in this folder with: gnuplot svd_figures.gp\n"
     << "if (!exists('suffix')) suffix = ''\n"
     << "set datafile separator ','\nset datafile columnheaders\n"
     << "set terminal pngcairo size 900,600 font ',11' noenhanced\nset grid\n\n";
  singularValuesPlot(gp, spec);
  timeFunctionsPlot(gp, spec);
  gp << "unset grid\n";
  modesPlot(gp, spec);
  return gp.str();
}

FigureStatus drawSvdFigures(const std::filesystem::path& dir, std::string& detail) {
  const PlotOutcome outcome = runPlots(dir, PlotJob{"svd_figures.gp", "", svdFigureNames(), false});
  switch (outcome.status) {
    case PlotStatus::Drawn: return FigureStatus::Drawn;
    case PlotStatus::GnuplotMissing:
      detail = "gnuplot is not on PATH: no PNG drawn (install gnuplot, then run 'gnuplot svd_figures.gp' in " +
               dir.string() + ")";
      return FigureStatus::GnuplotMissing;
    case PlotStatus::ScriptMissing:
    case PlotStatus::GnuplotFailed:
      detail = "gnuplot failed on " + (dir / "svd_figures.gp").string() + " (exit status " +
               std::to_string(outcome.exit_status) + "): no PNG replaced";
      return FigureStatus::GnuplotFailed;
    case PlotStatus::NotMoved: break;
  }
  detail = outcome.detail;
  return FigureStatus::GnuplotFailed;
}

}  // namespace stc
