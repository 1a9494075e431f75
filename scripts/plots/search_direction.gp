# gnuplot -e "data='results/search_direction'; out='docs/figures/search_direction.png'; omegas='1.0 0.97 0.95 0.9 0.8 0.6'; wbest='0.95'" scripts/plots/search_direction.gp
# Called by scripts/search_direction_study.sh, reads its plot_*.dat. Plain-LATIN iterations against the
# search-direction scale kappa: (left) to true error <= 1e-6 on the seed scene, one curve per omega;
# (middle) to indicator <= 1e-6, same runs; (right) to true error <= 1e-6 on the seed scene, a finer
# mesh (arc_nodes 201, 401) and a higher friction, at omega = 1 (dashed) and the best omega (solid). Points that did not
# reach the threshold within the cap are left out.
set terminal pngcairo size 1200,400 font ",9" noenhanced
set output out
set multiplot layout 1,3
set logscale xy
set grid
set xlabel "kappa  (k = kappa E l_i / L)"
set key bottom center
set title "seed: iterations to TRUE error <= 1e-6"
plot for [i=1:words(omegas)] data."/plot_seed.dat" using 1:(column(2*i+1)) \
     with linespoints lw 2 pt 7 ps 0.5 title "omega = ".word(omegas, i)
set title "seed: iterations to indicator <= 1e-6"
plot for [i=1:words(omegas)] data."/plot_seed.dat" using 1:(column(2*i)) \
     with linespoints lw 2 pt 7 ps 0.5 title "omega = ".word(omegas, i)
set title "optimum vs scene: iterations to TRUE error <= 1e-6"
# The plot command and its inline data are written by the study script (one series per scene and omega).
load data."/plot_variants.gp"
unset multiplot
