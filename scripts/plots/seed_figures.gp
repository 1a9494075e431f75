# gnuplot -e "run='results/hemicylinder'" scripts/plots/seed_figures.gp
# Draws, from the CSV files of solved runs (<run>/{incremental,latin,fas-apriori}/): the convergence
# of LATIN and of the default solver fas-apriori (indicator and true error against relaxations), the
# contact forces of fas-apriori and of the incremental solver against time, and the contact pressure
# along the arc at a few instants.
set datafile separator ","
set terminal pngcairo size 900,600 font ",11" noenhanced
set key top right
set grid

set output run."/figures/convergence.png"
set title "Seed scene: convergence (true error: relative energy error vs incremental)"
set logscale y
set format y "1e%T"
set xlabel "fine relaxations (LATIN iterations)"
set ylabel "indicator / true error"
plot run."/latin/history.csv"       every ::1 using 2:3 with lines lw 2 dt 2 lc 1 title "LATIN indicator", \
     ""                             every ::1 using 2:4 with lines lw 2 lc 1 title "LATIN true error", \
     run."/fas-apriori/history.csv" every ::1 using 2:3 with linespoints lw 2 dt 2 pt 6 lc 2 title "fas-apriori indicator", \
     ""                             every ::1 using 2:4 with linespoints lw 2 pt 7 lc 2 title "fas-apriori true error"
unset logscale y
set format y "%g"

set output run."/figures/reactions.png"
set title "Seed scene: total contact forces on the body"
set xlabel "t"
set ylabel "force (N/mm)"
set key top left
plot run."/incremental/reactions.csv" every ::1 using 2:3 with lines lw 3 title "normal (incremental)", \
     run."/fas-apriori/reactions.csv" every ::1 using 2:3 with points pt 6 ps 0.6 title "normal (fas-apriori)", \
     run."/incremental/reactions.csv" every ::1 using 2:4 with lines lw 3 title "tangential (incremental)", \
     run."/fas-apriori/reactions.csv" every ::1 using 2:4 with points pt 6 ps 0.6 title "tangential (fas-apriori)"

set output run."/figures/pressure.png"
set title "Seed scene: contact pressure along the arc (incremental)"
set xlabel "x"
set ylabel "pressure (MPa)"
set xrange [-0.4:0.4]
plot for [k in "60 100 150 200"] run."/incremental/contact.csv" \
     using (column(1) == k+0 ? column(4) : NaN):8 with linespoints pt 7 ps 0.5 title "t = ".sprintf("%.2f", (k+0)/200.0)
