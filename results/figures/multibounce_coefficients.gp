set terminal pngcairo size 1500,500 font ',10'
set output 'results/figures/multibounce_coefficients.png'
set multiplot layout 1,3 title 'cubic coefficients against the albedo'
set xrange [0:1]
set xlabel 'albedo'
set grid
set key bottom left font ',8'
set title 'a'
plot 'results/figures/multibounce_coefficients.dat' index 0 using 1:2:3 with yerrorbars pt 7 lc rgb 'black' title 'per-albedo fit (± s.e.)', '' index 1 using 1:2 with lines lw 2 lc rgb '#1f77b4' title 'gtlab joint linear', '' index 1 using 1:5 with lines lw 2 lc rgb '#d62728' title 'talk', '' index 1 using 1:8 with lines dt 2 lc rgb '#2ca02c' title 'gtlab joint quadratic', '' index 1 using 1:11 with lines dt 4 lc rgb '#9467bd' title 'gtlab joint anchored'
set title 'b'
plot 'results/figures/multibounce_coefficients.dat' index 0 using 1:4:5 with yerrorbars pt 7 lc rgb 'black' title 'per-albedo fit (± s.e.)', '' index 1 using 1:3 with lines lw 2 lc rgb '#1f77b4' title 'gtlab joint linear', '' index 1 using 1:6 with lines lw 2 lc rgb '#d62728' title 'talk', '' index 1 using 1:9 with lines dt 2 lc rgb '#2ca02c' title 'gtlab joint quadratic', '' index 1 using 1:12 with lines dt 4 lc rgb '#9467bd' title 'gtlab joint anchored'
set title 'c'
plot 'results/figures/multibounce_coefficients.dat' index 0 using 1:6:7 with yerrorbars pt 7 lc rgb 'black' title 'per-albedo fit (± s.e.)', '' index 1 using 1:4 with lines lw 2 lc rgb '#1f77b4' title 'gtlab joint linear', '' index 1 using 1:7 with lines lw 2 lc rgb '#d62728' title 'talk', '' index 1 using 1:10 with lines dt 2 lc rgb '#2ca02c' title 'gtlab joint quadratic', '' index 1 using 1:13 with lines dt 4 lc rgb '#9467bd' title 'gtlab joint anchored'
unset multiplot

unset output
