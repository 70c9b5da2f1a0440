set terminal pngcairo size 800,500 font ',10'
set output 'results/figures/gtao_convergence.png'
set termoption font ',12'
set logscale xy
set xlabel 'slices x samples per side'
set ylabel 'RMSE'
set title 'GTAO on boxes: regular slices, no denoiser'
set key outside
plot for [i=0:3] 'results/gtao/gtao_convergence.dat' index i using 3:4 with linespoints title sprintf('vs height field, %d steps', 2**(i+1)), for [i=0:3] 'results/gtao/gtao_convergence.dat' index i using 3:5 with lines dashtype 2 title sprintf('vs 3-D, %d steps', 2**(i+1))

unset output
