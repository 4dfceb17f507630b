set terminal pngcairo size 900,600 noenhanced
set output 'study.png'
set logscale xy
set xlabel 'wall time [s]'
set ylabel 'period'
set title 'oscillating_plate_enog: period against run time'
set key outside
set grid
plot for [i=0:0] 'study.dat' index i using 1:2 with linespoints title columnheader(1), \
     for [i=0:0] 'study.dat' index i using 1:2:3 with labels offset 1,0.7 notitle
