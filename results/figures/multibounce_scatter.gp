set terminal pngcairo size 1600,850 font ',10'
set output 'results/figures/multibounce_scatter.png'
set multiplot layout 2,4 title "V'_d against V_d, 4 bounces, 5 scenes"
set xrange [0:1]
set yrange [0:1]
set key top left font ',8'
set xlabel 'V_d'
set ylabel "V'_d"
set grid
set title 'albedo 0.1'
plot 'results/figures/multibounce_scatter.dat' index 0 using 1:2 with points pt 7 ps 0.15 lc rgb '#a0a0a0' title 'samples', 'results/figures/multibounce_curves.dat' index 0 using 1:2 with lines lw 2 lc rgb '#d62728' title 'talk', '' index 0 using 1:3 with lines lw 2 lc rgb '#1f77b4' title 'gtlab joint', '' index 0 using 1:4 with lines lw 1 dt 2 lc rgb '#2ca02c' title 'own cubic', x with lines dt 3 lc rgb 'black' title 'V_d'
set title 'albedo 0.2'
plot 'results/figures/multibounce_scatter.dat' index 1 using 1:2 with points pt 7 ps 0.15 lc rgb '#a0a0a0' title 'samples', 'results/figures/multibounce_curves.dat' index 1 using 1:2 with lines lw 2 lc rgb '#d62728' title 'talk', '' index 1 using 1:3 with lines lw 2 lc rgb '#1f77b4' title 'gtlab joint', '' index 1 using 1:4 with lines lw 1 dt 2 lc rgb '#2ca02c' title 'own cubic', x with lines dt 3 lc rgb 'black' title 'V_d'
set title 'albedo 0.3'
plot 'results/figures/multibounce_scatter.dat' index 2 using 1:2 with points pt 7 ps 0.15 lc rgb '#a0a0a0' title 'samples', 'results/figures/multibounce_curves.dat' index 2 using 1:2 with lines lw 2 lc rgb '#d62728' title 'talk', '' index 2 using 1:3 with lines lw 2 lc rgb '#1f77b4' title 'gtlab joint', '' index 2 using 1:4 with lines lw 1 dt 2 lc rgb '#2ca02c' title 'own cubic', x with lines dt 3 lc rgb 'black' title 'V_d'
set title 'albedo 0.4'
plot 'results/figures/multibounce_scatter.dat' index 3 using 1:2 with points pt 7 ps 0.15 lc rgb '#a0a0a0' title 'samples', 'results/figures/multibounce_curves.dat' index 3 using 1:2 with lines lw 2 lc rgb '#d62728' title 'talk', '' index 3 using 1:3 with lines lw 2 lc rgb '#1f77b4' title 'gtlab joint', '' index 3 using 1:4 with lines lw 1 dt 2 lc rgb '#2ca02c' title 'own cubic', x with lines dt 3 lc rgb 'black' title 'V_d'
set title 'albedo 0.5'
plot 'results/figures/multibounce_scatter.dat' index 4 using 1:2 with points pt 7 ps 0.15 lc rgb '#a0a0a0' title 'samples', 'results/figures/multibounce_curves.dat' index 4 using 1:2 with lines lw 2 lc rgb '#d62728' title 'talk', '' index 4 using 1:3 with lines lw 2 lc rgb '#1f77b4' title 'gtlab joint', '' index 4 using 1:4 with lines lw 1 dt 2 lc rgb '#2ca02c' title 'own cubic', x with lines dt 3 lc rgb 'black' title 'V_d'
set title 'albedo 0.7'
plot 'results/figures/multibounce_scatter.dat' index 5 using 1:2 with points pt 7 ps 0.15 lc rgb '#a0a0a0' title 'samples', 'results/figures/multibounce_curves.dat' index 5 using 1:2 with lines lw 2 lc rgb '#d62728' title 'talk', '' index 5 using 1:3 with lines lw 2 lc rgb '#1f77b4' title 'gtlab joint', '' index 5 using 1:4 with lines lw 1 dt 2 lc rgb '#2ca02c' title 'own cubic', x with lines dt 3 lc rgb 'black' title 'V_d'
set title 'albedo 0.9'
plot 'results/figures/multibounce_scatter.dat' index 6 using 1:2 with points pt 7 ps 0.15 lc rgb '#a0a0a0' title 'samples', 'results/figures/multibounce_curves.dat' index 6 using 1:2 with lines lw 2 lc rgb '#d62728' title 'talk', '' index 6 using 1:3 with lines lw 2 lc rgb '#1f77b4' title 'gtlab joint', '' index 6 using 1:4 with lines lw 1 dt 2 lc rgb '#2ca02c' title 'own cubic', x with lines dt 3 lc rgb 'black' title 'V_d'
unset multiplot

unset output
