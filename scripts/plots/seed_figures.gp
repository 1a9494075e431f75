# gnuplot -e "run='results/hemicylinder'" scripts/plots/seed_figures.gp
# Draws, from the CSV files of a solved run: LATIN's convergence (indicator and true error against
# iterations), the contact forces of LATIN and of the incremental solver against time, and the
# contact pressure along the arc at a few instants.
set datafile separator ","
set terminal pngcairo size 900,600 font ",11" noenhanced
set key top right
set grid

set output run."/figures/convergence.png"
set title "Seed scene: LATIN convergence (true error: relative energy error vs incremental)"
set logscale y
set format y "1e%T"
set xlabel "iteration (= relaxations)"
set ylabel "indicator / true error"
plot run."/latin/history.csv" every ::1 using 1:3 with lines lw 2 title "indicator", \
     ""                       every ::1 using 1:4 with lines lw 2 title "true error"
unset logscale y
set format y "%g"

set output run."/figures/reactions.png"
set title "Seed scene: total contact forces on the body"
set xlabel "t"
set ylabel "force (N/mm)"
set key top left
plot run."/incremental/reactions.csv" every ::1 using 2:3 with lines lw 3 title "normal (incremental)", \
     run."/latin/reactions.csv"       every ::1 using 2:3 with points pt 6 ps 0.6 title "normal (LATIN)", \
     run."/incremental/reactions.csv" every ::1 using 2:4 with lines lw 3 title "tangential (incremental)", \
     run."/latin/reactions.csv"       every ::1 using 2:4 with points pt 6 ps 0.6 title "tangential (LATIN)"

set output run."/figures/pressure.png"
set title "Seed scene: contact pressure along the arc (incremental)"
set xlabel "x"
set ylabel "pressure (MPa)"
set xrange [-0.4:0.4]
plot for [k in "60 100 150 200"] run."/incremental/contact.csv" \
     using (column(1) == k+0 ? column(3) : NaN):7 with linespoints pt 7 ps 0.5 title "t = ".sprintf("%.2f", (k+0)/200.0)
