set terminal pngcairo size 1000,560 font ',10'
set output 'results/figures/atmosphere_sizes.png'
set logscale xy
set xrange [500:2e6]
set xlabel 'table size [bytes]'
set ylabel '95th percentile of the relative error'
set title 'Decima atmosphere LUTs: error against memory (one axis at a time from the talk size)'
set key outside right
set arrow from graph 0, first 0.02 to graph 1, first 0.02 nohead dashtype 2
plot 'results/luts/atmosphere_sizes.dat' using ($1 == 0 ? $2 : 1/0):6 with points pt 7 title 'in-scatter', '' using ($1 == 1 ? $2 : 1/0):6 with points pt 5 title 'sun', '' using ($1 == 2 ? $2 : 1/0):6 with points pt 9 title 'sky', '' using ($1 == 0 ? $2 : 1/0):4 with points pt 6 title 'in-scatter, interpolation max'

unset output
