# The million-dof solve's history (scripts/million_dofs.sh; docs/linear_solvers.md, "A million
# degrees of freedom"), drawn from the run's history.csv: the error estimate and the indicator
# against wall time (left; the true error too when the run had a reference), and the sparse solves
# and Krylov iterations so far (right).
# Variables, given with -e:
#   run    the run folder (holding history.csv)
#   title  the run's description, for the titles
#   png    the PNG to write
# Example:
#   gnuplot -e "run='results/million_dofs_d44_np2'; title='1.07M dofs, 2 ranks'; png='m.png'" \
#           scripts/plots/million_dofs.gp
if (!exists('title')) title = ''
csv = run . '/history.csv'
set datafile separator ','
set datafile columnheaders
# columns: 1 iteration, 2 relaxations, 3 indicator, 4 error, 5 rank, 6 wall_s, 7 error_estimate,
#          8 sparse_solves, 9 krylov_iterations
set terminal pngcairo size 1400,560 font ',11'
set output png
set multiplot layout 1,2 title 'fas-apriori on CG + GAMG, ' . title
set xlabel 'wall time (s)'
set grid
set key top right

set title 'error estimate against wall time'
set logscale y
set format y '10^{%L}'
set ylabel 'estimate, indicator'
plot csv using 6:(valid(7) ? column(7) : NaN) with linespoints pt 7 ps 0.8 lc rgb '#d62728' title 'error estimate', \
     csv using 6:3 with linespoints pt 6 ps 0.8 lc rgb '#ff9896' title 'indicator', \
     csv using 6:(valid(4) && column(4) > 0 ? column(4) : NaN) with linespoints pt 5 ps 0.8 lc rgb '#202020' \
       title 'true error (with a reference)', \
     1e-6 with lines dt 2 lc rgb '#202020' title 'tolerance'

set title 'sparse solves and Krylov iterations so far'
unset logscale y
set format y '%g'
set ylabel 'sparse solves'
set y2label 'Krylov iterations'
set y2tics
set key top left
plot csv using 6:8 with linespoints pt 7 ps 0.8 lc rgb '#d62728' title 'sparse solves', \
     csv using 6:9 axes x1y2 with lines lc rgb '#1f77b4' title 'Krylov iterations'
unset multiplot
