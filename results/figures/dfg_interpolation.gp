set terminal pngcairo size 900,520 font ',10'
set output 'results/figures/dfg_interpolation.png'
set logscale xy
set xrange [10:400]
set xlabel 'table size N (N x N)'
set ylabel 'RMS error between texel centres'
set title 'DFG LUT: bilinear lookup against the quadrature'
set key top right
set arrow from 128, graph 0 to 128, graph 1 nohead dashtype 2
set label 'Filament' at 128, graph 0.95 right offset -0.5,0
plot 'results/luts/dfg_interpolation.dat' using 1:5 with linespoints title 'A', '' using 1:9 with linespoints title 'B', '' using 1:13 with linespoints title 'E = A + B'

unset output
