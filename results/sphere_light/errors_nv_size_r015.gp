set terminal pngcairo size 2000,460 font ',10'
set output 'results/sphere_light/errors_nv_size_r015.png'
set datafile separator ','
set multiplot layout 1,4 title 'roughness 0.15: mean |ln((approx + 0.01)/(reference + 0.01))| near the highlight'
set xlabel 'n.v'
set ylabel 'angular radius (deg)'
set logscale y
set palette rgb 21,22,23
set cbrange [0:1]
set xrange [0.05:1]
set yrange [0.266426:30]
set title 'Karis'
plot 'results/sphere_light/errors_nv_size_r015.csv' using 1:2:3 with image notitle
set title 'Decima (published)'
plot 'results/sphere_light/errors_nv_size_r015.csv' using 1:2:4 with image notitle
set title 'Decima refit'
plot 'results/sphere_light/errors_nv_size_r015.csv' using 1:2:5 with image notitle
set title 'LTC'
plot 'results/sphere_light/errors_nv_size_r015.csv' using 1:2:6 with image notitle
unset multiplot

unset output
