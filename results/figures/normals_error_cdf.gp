set terminal pngcairo size 900,520 font ',10'
set output 'results/figures/normals_error_cdf.png'
set xlabel 'angular error (degrees)'
set ylabel 'percentile'
set logscale x
set xrange [0.003:1]
set title 'G-buffer normals: error distribution over random directions'
set key bottom right
plot 'results/best_fit_normals/error_cdf.dat' using 2:1 with lines title 'RGB8 normalised', '' using 3:1 with lines title 'RGB8 / max', '' using 4:1 with lines title 'RGB8 best fit (table)', '' using 5:1 with lines title 'best fit, bilinear', '' using 6:1 with lines title 'RGB8 best cell', '' using 10:1 with lines title 'octahedral 2x10 precise', '' using 12:1 with lines title 'octahedral 2x12 precise'

unset output
