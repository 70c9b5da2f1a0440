set terminal pngcairo size 1200,500 font ',10'
set output 'results/sphere_light/sphere_noh_map.png'
set datafile separator ','
set multiplot layout 1,2 title 'GetNoHSquared: one Newton step against Karis (mean over light size and azimuth)'
set xlabel 'n.v'
set ylabel 'light elevation from n (deg)'
set palette defined (-1 'red', 0 'white', 1 'blue')
set title 'gain in (N.H)^2 (blue: the step helps)'
stats 'results/sphere_light/sphere_noh_map.csv' using 3 nooutput
m = (abs(STATS_min) > abs(STATS_max) ? abs(STATS_min) : abs(STATS_max))
set cbrange [-m:m]
plot 'results/sphere_light/sphere_noh_map.csv' using 1:2:3 with image notitle
set palette defined (0 'white', 1 'red')
set cbrange [0:*]
set title 'share of configurations where the step is worse'
plot 'results/sphere_light/sphere_noh_map.csv' using 1:2:4 with image notitle
unset multiplot

unset output
