# gnuplot couette.gp (in this folder): series.csv, disorder.csv -> couette.png
set terminal pngcairo size 1100,1150 noenhanced
set output 'couette.png'
set datafile separator ','
set datafile missing 'nan'
set multiplot layout 3,1
set grid
set key outside right
set xlabel 'shear times (gamma t)'
set xrange [0:20]
set ylabel 'omega / (gamma/2)'
set yrange [0.75:1.15]
set title 'free cylinder, H = 8a, period 16a, a = 4 dp unless a6: rotation rate'
plot 0.9645 with lines lw 2 lc rgb 'black' title 'Stokes 0.9645', \
     for [i=0:3] 'series.csv' using 1:(column(2+2*i)) every ::1 with lines title columnhead(2+2*i)
set ylabel 'smallest pair distance / dp'
set yrange [0:1.05]
set title 'smallest pair distance (run guard 0.1 dp); P_: plane Couette from a jittered lattice'
plot for [i=0:5] 'series.csv' using 1:(column(3+2*i)) every ::1 with lines title columnhead(3+2*i)
set ylabel 'spread of nearest-neighbour distance / dp'
set logscale y
set yrange [1e-4:0.3]
set title 'disorder of the fluid: standard deviation of the nearest-neighbour distance (frames)'
plot for [i=0:7] 'disorder.csv' using 1:(column(2+2*i)) with linespoints title columnhead(2+2*i)
unset multiplot
