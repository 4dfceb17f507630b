# Tip stiffness error of the cantilever (cases/beam_bending) against particles across the height:
# total Lagrangian for five hourglass alphas, Eulerian + hourglass, non-hourglass ULSPH (beam.dat).
set terminal pngcairo size 1100,600 noenhanced
set output 'beam.png'
set logscale xy
set xrange [3.5:18]
set xtics (4, 8, 16)
set xlabel 'particles across the height n (N = (3 + 8n) n in Ganzenmueller 2015)'
set ylabel '|f/u - C_EB| / C_EB'
set title 'cantilever, tip displacement 0.1 mm: stiffness error against resolution'
set key outside right
set grid
plot for [k=0:4] 'beam.dat' index k using 1:3 with linespoints title sprintf('total Lagrangian, alpha = %d', 25*k), \
     'beam.dat' index 5 using 1:3 with linespoints dt 2 title 'Eulerian xi = 1, corrected', \
     'beam.dat' index 6 using 1:3 with linespoints dt 3 title 'non-hourglass, cubic', \
     'beam.dat' index 7 using 1:3 with linespoints dt 3 title 'non-hourglass, Wendland', \
     0.4*(4/x)**2 with lines lc rgb 'gray' title 'slope -2'
