# Work-precision plots of `stcontact compare` (docs/compare.md), drawn from work_precision.csv in
# the current folder (the report's): true error against wall time (log-log), against relaxations and
# against sparse solves. One line per iterative strategy (the repeat named in `repeats`: the median
# one by total time), the exact (incremental) solver as points at the bottom of the error axis, its
# error being 0, and a dashed vertical line at its time / sparse solves.
# Variables, given with -e (`stcontact compare` prints the exact line when it cannot draw):
#   curves     strategies drawn as lines, space-separated, e.g. 'latin fas-aposteriori'
#   repeats    the repeat drawn for each, in the same order, e.g. '2 1'
#   reference  the exact solver drawn as points, e.g. 'incremental', or ''
#   scene      the scene's name, for the titles
#   suffix     appended to each PNG name (the command draws into NAME.png.tmp, then renames)
# Example, in results/hemicylinder/compare:
#   gnuplot -e "curves='latin fas-aposteriori'; repeats='2 2'; reference='incremental'; scene='hemicylinder'" \
#           ../../../scripts/plots/work_precision.gp
if (!exists('curves')) curves = ''
if (!exists('repeats')) repeats = ''
if (!exists('reference')) reference = ''
if (!exists('scene')) scene = ''
if (!exists('suffix')) suffix = ''

# One colour per strategy in every report (the same line in work_precision.gp, scaling.gp and
# studies/programs/compare_bases.cpp's script): latin blue, latin-pgd orange, fas-aposteriori green,
# fas-apriori red, incremental black, any other purple.
colour(s) = s eq 'latin' ? '#1f77b4' : s eq 'latin-pgd' ? '#ff7f0e' : s eq 'fas-aposteriori' ? '#2ca02c' : s eq 'fas-apriori' ? '#d62728' : s eq 'incremental' ? '#202020' : '#9467bd'

csv = 'work_precision.csv'
set datafile separator ','
set datafile columnheaders
# columns: 1 solver, 2 repeat, 3 iteration, 4 relaxations, 5 sparse_solves, 6 indicator, 7 error, 8 wall_s
on(i) = strcol(1) eq word(curves, i) && column(2) == word(repeats, i) + 0 && valid(7) && column(7) > 0
curve(i, x) = on(i) ? column(x) : NaN
ref(x) = strcol(1) eq reference ? column(x) : NaN
n_ref = strlen(reference) > 0 ? 1 : 0

# The bottom of the error axis: a decade below the smallest error drawn; the reference sits there.
lowest = 1e-12
if (words(curves) > 0) {
  stats csv using (strcol(1) ne reference && valid(7) && column(7) > 0 ? column(7) : NaN) nooutput
  lowest = STATS_min
}
bottom = 10**(floor(log10(lowest)) - 1)
ref_time = 0
ref_solves = 0
if (n_ref) {
  stats csv using (ref(8)) nooutput
  ref_time = STATS_median
  stats csv using (ref(5)) nooutput
  ref_solves = STATS_median
}

set terminal pngcairo size 900,600 font ',11' noenhanced
set grid
set key below
set logscale y
set format y '1e%T'
set yrange [bottom / 2 : *]
set ylabel 'true error (relative energy, docs/method.md §2)'
ref_title = reference.' (exact: error 0, drawn at the bottom)'

set output 'error_vs_time.png'.suffix
set title scene.': true error against wall time (median repeat)'
set xlabel 'wall time since the solver was called (s)'
set logscale x
if (n_ref) { set arrow 1 from ref_time, graph 0 to ref_time, graph 1 nohead dt 2 lc rgb 'gray40' }
plot for [i=1:words(curves)] csv using (curve(i, 8)):(curve(i, 7)) with linespoints pt 7 ps 0.4 lw 2 \
       lc rgb colour(word(curves, i)) title word(curves, i), \
     for [j=1:n_ref] csv using (ref(8)):(ref(8) == ref(8) ? bottom : NaN) with points pt 5 ps 1.5 \
       lc rgb 'black' title ref_title

set output 'error_vs_relaxations.png'.suffix
set title scene.': true error against fine LATIN relaxations (median repeat)'
set xlabel 'relaxations (global + local stage pairs)'
unset logscale x
unset arrow 1
plot for [i=1:words(curves)] csv using (curve(i, 4)):(curve(i, 7)) with linespoints pt 7 ps 0.4 lw 2 \
       lc rgb colour(word(curves, i)) title word(curves, i), \
     for [j=1:n_ref] csv using (ref(4)):(ref(4) == ref(4) ? bottom : NaN) with points pt 5 ps 1.5 \
       lc rgb 'black' title reference.' (no relaxation: error 0 at 0)'

set output 'error_vs_sparse_solves.png'.suffix
set title scene.': true error against right-hand sides solved with a sparse factor (median repeat)'
set xlabel 'sparse solves (right-hand sides)'
set logscale x
if (n_ref) { set arrow 1 from ref_solves, graph 0 to ref_solves, graph 1 nohead dt 2 lc rgb 'gray40' }
plot for [i=1:words(curves)] csv using (curve(i, 5)):(curve(i, 7)) with linespoints pt 7 ps 0.4 lw 2 \
       lc rgb colour(word(curves, i)) title word(curves, i), \
     for [j=1:n_ref] csv using (ref(5)):(ref(5) == ref(5) ? bottom : NaN) with points pt 5 ps 1.5 \
       lc rgb 'black' title ref_title
unset output
