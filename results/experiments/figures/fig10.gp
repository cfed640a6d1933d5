# Run from the report folder: gnuplot figures/fig10.gp
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1200,400 font 'Sans,10'
} else {
  set terminal png size 1200,400
}
set grid
set key outside right top
set termoption noenhanced
set datafile separator ','
set output 'figures/fig10.png'
set key autotitle columnheader
set multiplot layout 1,2 title 'Fig. 10: NDT (paper''s layer-2 cell), 3dtk 0_1'
set title 'NDT: translation'
set xlabel 'iteration'
set ylabel 'parameter error [cm]'
plot 'csv/trace_ndt.csv' using 1:5 with linespoints title 'tx (lateral)', '' using 1:6 with linespoints title 'ty (vertical)', '' using 1:7 with linespoints title 'tz (forward)'
set title 'NDT: rotation'
set ylabel 'parameter error [deg]'
plot 'csv/trace_ndt.csv' using 1:8 with linespoints title 'alpha', '' using 1:9 with linespoints title 'beta (heading)', '' using 1:10 with linespoints title 'gamma'
unset multiplot
