set terminal pngcairo size 900,600 noenhanced
set output 'study.png'
set xlabel 'variables.angle'
set ylabel 'removed_mass'
set title 'erosion_map: removed_mass against variables.angle'
set key outside
set grid
set yrange [0:*]
plot for [i=0:3] 'study.dat' index i using 1:2 with linespoints title columnheader(1)
