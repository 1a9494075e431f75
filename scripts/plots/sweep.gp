# Plot of `stcontact sweep` (docs/sweep.md), drawn from sweep.csv in the current folder (the report's):
# fine LATIN relaxations (top) and wall time (bottom) per value of the swept key, the warm-started
# solves (each from the previous value's solution) against the cold ones (each from zero).
# Variables, given with -e (`stcontact sweep` prints the exact line when it cannot draw):
#   key     the swept scene key, for the x axis, e.g. 'contact.friction'
#   scene   the scene's name, for the title
#   solver  the strategy, for the title
#   cold    1 when sweep.csv has cold solves, 0 with --no-independent
#   suffix  appended to the PNG name (the command draws into NAME.png.tmp, then renames)
# Example, in results/hemicylinder/sweep_contact.friction:
#   gnuplot -e "key='contact.friction'; scene='hemicylinder'; solver='fas-apriori'; cold=1" \
#           ../../../scripts/plots/sweep.gp
if (!exists('key')) key = 'value'
if (!exists('scene')) scene = ''
if (!exists('solver')) solver = ''
if (!exists('cold')) cold = 1
if (!exists('suffix')) suffix = ''

csv = 'sweep.csv'
set datafile separator ','
set datafile columnheaders
# columns: 1 value, 5 warm_relaxations, 7 warm_wall_s, 11 cold_relaxations, 13 cold_wall_s
set terminal pngcairo size 900,900 font ',11' noenhanced
set output 'sweep.png'.suffix
set grid
set key top left
set multiplot layout 2,1 title scene.', '.solver.': warm start from the previous value against cold start'

set ylabel 'relaxations (global + local stage pairs)'
set yrange [0:*]
plot csv using 1:5 with linespoints pt 7 lw 2 title 'warm', \
     for [c=1:cold] csv using 1:11 with linespoints pt 5 lw 2 dt 2 title 'cold'

set ylabel 'wall time (s, set-up included)'
set xlabel key
plot csv using 1:7 with linespoints pt 7 lw 2 title 'warm', \
     for [c=1:cold] csv using 1:13 with linespoints pt 5 lw 2 dt 2 title 'cold'

unset multiplot
unset output
