# Period error against wall time of the three solid formulations (the three study.dat files).
set terminal pngcairo size 900,600 noenhanced
set output 'formulations.png'
set logscale xy
set xlabel 'wall time [s] (1 thread, two runs at a time)'
set ylabel 'relative error of the period'
set title 'oscillating plate, 0.6 s: error against run time (10 and 20 particles across)'
set key top right
set grid
plot 'eulerian/study.dat' index 0 using 1:2 with linespoints title 'Eulerian + hourglass (MMB, xi = 0.5, gamma = 0.6)', \
     'total_lagrangian/study.dat' index 0 using 1:2 with linespoints title 'total Lagrangian (Ganzenmueller, alpha = 5, gamma = 0.6)', \
     'non_hourglass/study.dat' index 0 using 1:2 with linespoints title 'non-hourglass ULSPH (Zhang, Wendland, velocity Verlet)'
