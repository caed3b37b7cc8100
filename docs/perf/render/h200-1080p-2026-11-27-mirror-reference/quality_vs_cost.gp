if (!exists("outdir")) outdir = ''
set terminal pngcairo size 1000,650
set output outdir.'quality_vs_cost.png'
set grid
set xlabel 'GPU frame time (ms, 1920x1080)'
set ylabel 'RMSE vs path-traced reference (linear radiance)'
set title 'Realtime GI settings: error against cost (cottage, 3 views)'
set offsets graph 0.05, graph 0.35, graph 0.1, graph 0.1
plot 'quality_vs_cost.dat' using 2:3 with points pt 7 ps 1.5 notitle, '' using 2:3:1 with labels offset char 1,0.6 left notitle
set terminal svg size 1000,650
set output outdir.'quality_vs_cost.svg'
set grid
set xlabel 'GPU frame time (ms, 1920x1080)'
set ylabel 'RMSE vs path-traced reference (linear radiance)'
set title 'Realtime GI settings: error against cost (cottage, 3 views)'
set offsets graph 0.05, graph 0.35, graph 0.1, graph 0.1
plot 'quality_vs_cost.dat' using 2:3 with points pt 7 ps 1.5 notitle, '' using 2:3:1 with labels offset char 1,0.6 left notitle
