# gnuplot couette.gp (in this folder): series.csv -> couette.png
set terminal pngcairo size 1000,800 noenhanced
set output 'couette.png'
set datafile separator ','
set multiplot layout 2,1
set grid
set key outside right
set xlabel 'shear times (gamma t)'
set ylabel 'omega / (gamma/2)'
set yrange [0.75:1.15]
set title 'free cylinder, H = 8a, period 16a, a = 4 dp: rotation rate (Stokes 0.9645)'
plot 0.9645 with lines lw 2 lc rgb 'black' title 'Stokes 0.9645', \
     for [i=0:3] 'series.csv' using 1:(column(2+2*i)) every ::1 with lines title columnhead(2+2*i)
set ylabel 'smallest pair distance / dp'
set yrange [0:1.05]
set title 'smallest pair distance (guard 0.1 dp)'
plot for [i=0:3] 'series.csv' using 1:(column(3+2*i)) every ::1 with lines title columnhead(3+2*i)
unset multiplot
