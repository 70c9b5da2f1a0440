set terminal pngcairo size 1000,560 font ',10'
set output 'results/figures/volumetric_error_vs_spp.png'
set logscale xy
set xlabel 'samples per pixel (steps per ray)'
set ylabel 'relative RMSE'
set title 'INSIDE volume light: ray-march error against the reference (solid: 1 frame, dashed: 16 frames accumulated)'
set key outside right
set arrow from graph 0, first 0.00049708 to graph 1, first 0.00049708 nohead dashtype 3
plot 'results/volumetric_light/error_vs_spp.dat' using 1:2 with linespoints lc 1 dt 1 title 'none', '' using 1:3 with linespoints lc 1 dt 2 notitle, 'results/volumetric_light/error_vs_spp.dat' using 1:4 with linespoints lc 2 dt 1 title 'white', '' using 1:5 with linespoints lc 2 dt 2 notitle, 'results/volumetric_light/error_vs_spp.dat' using 1:6 with linespoints lc 3 dt 1 title 'bayer', '' using 1:7 with linespoints lc 3 dt 2 notitle, 'results/volumetric_light/error_vs_spp.dat' using 1:8 with linespoints lc 4 dt 1 title 'ign', '' using 1:9 with linespoints lc 4 dt 2 notitle, 'results/volumetric_light/error_vs_spp.dat' using 1:10 with linespoints lc 5 dt 1 title 'blue', '' using 1:11 with linespoints lc 5 dt 2 notitle

unset output
