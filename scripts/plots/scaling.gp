# Plots of `stcontact scaling` (docs/scaling.md), drawn from scaling.csv in the current folder (the
# report's): time to first reach the target true error against the number of instants m (time
# series) and against the dofs (mesh series), log-log, one line per strategy; peak resident memory
# against the same sizes. A size where a strategy did not reach the target has no point.
# Variables, given with -e (`stcontact scaling` prints the exact line when it cannot draw):
#   solvers    strategies, space-separated, e.g. 'latin fas-apriori incremental'
#   target     the target error's label, e.g. '1e-4'
#   scene      the scene's name, for the titles
#   series     the series that have sizes: 'time mesh', 'time' or 'mesh'
#   suffix     appended to each PNG name (the command draws into NAME.png.tmp, then renames)
#   timecol    the time drawn: 'time_to_target_s' (default: first reach) or 'time_at_tolerance_s'
#              (the solves at tolerance; --only-at-tolerance)
#   incremental_forms  the incremental solver's forms at tolerance, e.g. 'interface, whole-body'
#              (its legend reads 'incremental (interface, whole-body)'; empty: 'incremental')
# Example, in results/hemicylinder/scaling:
#   gnuplot -e "solvers='latin fas-apriori incremental'; target='1e-4'; scene='hemicylinder'; series='time mesh'" \
#           ../../../scripts/plots/scaling.gp
if (!exists('solvers')) solvers = ''
if (!exists('target')) target = '1e-4'
if (!exists('scene')) scene = ''
if (!exists('series')) series = 'time mesh'
if (!exists('suffix')) suffix = ''
if (!exists('timecol')) timecol = 'time_to_target_s'
if (!exists('incremental_forms')) incremental_forms = ''
at_tolerance = timecol eq 'time_at_tolerance_s'
memcol = at_tolerance ? 'peak_rss_mb_at_tolerance' : 'peak_rss_mb'

csv = 'scaling.csv'
set datafile separator ','
set datafile columnheaders
# Value of column `y` on the rows of strategy i in series s, NaN elsewhere (or when empty).
pick(s, i, y) = strcol('series') eq s && strcol('solver') eq word(solvers, i) && strlen(strcol(y)) > 0 ? column(y) : NaN

set terminal pngcairo size 900,600 font ',11' noenhanced
set grid
set key below
set logscale xy
set format y '%g'

# One colour per strategy in every report (the same line in work_precision.gp, scaling.gp and
# studies/programs/compare_bases.cpp's script): latin blue, latin-pgd orange, fas-aposteriori green,
# fas-apriori red, incremental black, any other purple.
# The legend of strategy s: the incremental solver's with the forms that solved.
legend(s) = s eq 'incremental' && strlen(incremental_forms) > 0 ? s.' ('.incremental_forms.')' : s
colour(s) = s eq 'latin' ? '#1f77b4' : s eq 'latin-pgd' ? '#ff7f0e' : s eq 'fas-aposteriori' ? '#2ca02c' : s eq 'fas-apriori' ? '#d62728' : s eq 'incremental' ? '#202020' : '#9467bd'

do for [k=1:words(series)] {
  s = word(series, k)
  xcol = s eq 'time' ? 'steps' : 'dofs'
  xlab = s eq 'time' ? 'instants m (mesh of the scene)' : 'dofs (instants of the scene)'
  name = s eq 'time' ? 'steps' : 'dofs'
  set xlabel xlab
  set output 'time_vs_'.name.'.png'.suffix
  set title at_tolerance ? scene.': time of a solve at tolerance '.target.' against '.name.' (median of repeats)' \
                         : scene.': time to reach true error '.target.' against '.name.' (median of repeats)'
  set ylabel at_tolerance ? 'wall time at tolerance '.target.' (s, set-up included)' \
                          : 'time to reach '.target.' (s, set-up included)'
  plot for [i=1:words(solvers)] csv using (pick(s, i, xcol)):(pick(s, i, timecol)) \
       with linespoints pt 7 ps 0.8 lw 2 lc rgb colour(word(solvers, i)) title legend(word(solvers, i))
  set output 'memory_vs_'.name.'.png'.suffix
  set title at_tolerance ? scene.': peak resident memory of a solve at tolerance '.target.' against '.name \
                         : scene.': peak resident memory to reach '.target.' against '.name
  set ylabel 'peak resident memory (MB)'
  plot for [i=1:words(solvers)] csv using (pick(s, i, xcol)):(pick(s, i, memcol)) \
       with linespoints pt 7 ps 0.8 lw 2 lc rgb colour(word(solvers, i)) title legend(word(solvers, i))
}
unset output
