set terminal pngcairo size 900,520 font ',10'
set output 'results/figures/hdr_code_steps.png'
set logscale xy
set xlabel 'linear value x'
set ylabel 'step of one 8-bit code (linear units)'
set title '8-bit storage: gamma vs linear precision'
set key top left
set arrow from 0.235627, graph 0 to 0.235627, graph 1 nohead dashtype 2
set label 'equal (gamma 2.2)' at 0.235627, graph 0.1 left offset 0.5,0
set arrow from 0.454545, graph 0 to 0.454545, graph 1 nohead dashtype 3
set label 'the talk: 116/255' at 0.454545, graph 0.05 left offset 0.5,0
plot 'results/hdr_precision/code_steps.dat' using 1:2 with lines title 'linear', '' using 1:3 with lines title 'gamma 2.2', '' using 1:4 with lines title 'sRGB'

unset output
