set terminal pngcairo size 700,450 font ',10'
set output 'results/sphere_light/fit_profile.png'
set datafile separator ','
set xlabel 'radius reduction (published 0.25)'
set ylabel 'cost: 1/2 sum of squared log errors'
set key off
set title 'Decima refit: cost with the radius reduction held, normalisation refitted'
plot 'results/sphere_light/fit_profile.csv' using 1:2 skip 1 with points pt 7

unset output
