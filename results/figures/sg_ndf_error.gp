set terminal pngcairo size 900,520 font ',10'
set output 'results/figures/sg_ndf_error.png'
set logscale y
set xrange [0.5:9.5]
set xlabel 'lobes k'
set ylabel 'relative L2 error E (solid angle)'
set key outside right
set title 'NDF fit with spherical Gaussians'
set arrow from 7, graph 0 to 7, graph 1 nohead dashtype 2
set arrow from graph 0, first 0.05 to graph 1, first 0.05 nohead dashtype 3
plot 'results/sg_ndf/sg_ndf_error.dat' index 0 using 1:2 with linespoints dashtype 1 title 'ward 0.20 0.10', 'results/sg_ndf/sg_ndf_error.dat' index 1 using 1:2 with linespoints dashtype 1 title 'ward 0.40 0.20', 'results/sg_ndf/sg_ndf_error.dat' index 2 using 1:2 with linespoints dashtype 1 title 'ward 0.50 0.10', 'results/sg_ndf/sg_ndf_error.dat' index 3 using 1:2 with linespoints dashtype 2 title 'ggx 0.20 0.10', 'results/sg_ndf/sg_ndf_error.dat' index 4 using 1:2 with linespoints dashtype 2 title 'ggx 0.40 0.20', 'results/sg_ndf/sg_ndf_error.dat' index 5 using 1:2 with linespoints dashtype 2 title 'ggx 0.50 0.10'

unset output
