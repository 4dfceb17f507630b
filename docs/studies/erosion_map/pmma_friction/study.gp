set terminal pngcairo size 900,600 noenhanced
set output 'study.png'
set xlabel 'variables.speed'
set ylabel 'removed_mass'
set title 'erosion_map_pmma: removed_mass against variables.speed'
set key outside
set grid
set yrange [0:*]
plot for [i=0:1] 'study.dat' index i using 1:2 with linespoints title columnheader(1)
