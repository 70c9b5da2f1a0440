set terminal pngcairo size 800,500 font ',10'
set output 'results/sphere_light/sphere_noh_error.png'
set datafile separator ','
set key top right
set logscale y
set xlabel 'n.v'
set ylabel 'mean shortfall of (N.H)^2 below the maximum'
set title 'GetNoHSquared against the brute-force maximum'
plot 'results/sphere_light/sphere_noh_by_nv.csv' using 1:2 with linespoints title 'Karis (0 steps)', '' using 1:3 with linespoints title '1 Newton step (Decima)', '' using 1:4 with linespoints title '2 Newton steps', '' using 1:5 with linespoints title "1 step, guarded (f''(0) < 0)"

unset output
