set terminal pngcairo size 900,520 font ',10'
set output 'results/figures/normals_cells.png'
set logscale x 2
set xlabel 'cubemap face size (texels)'
set ylabel '% of the 256^3 cells used'
set title 'RGB8 normals: cells used, sampled on a cubemap vs exact'
set key at graph 0.98, graph 0.62
set logscale y
set yrange [1:120]
plot 'results/best_fit_normals/cells.dat' using 1:4 with linespoints title 'best fit (talk''s search)', 94.953108 title 'exact: distinct directions' dashtype 2, 98.2 title 'the talk: 98.2%' dashtype 3, '' using 1:2 with linespoints title 'normalised', 1.827526 title 'exact: sphere cells' dashtype 2, 1.73 title 'the talk: 1.73%' dashtype 3

unset output
