# Run from the report folder: gnuplot figures/reach_x.gp
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1000,500 font 'Sans,10'
} else {
  set terminal png size 1000,500
}
set grid
set key outside right top
set termoption noenhanced
set datafile separator ','
set output 'figures/reach_x.png'
set key autotitle columnheader
set key bottom left inside
set title 'Section 5.1: runs within tolerance against the start offset (along x, all data sets)'
set xlabel 'offset along x [m]'
set ylabel 'runs within tolerance [%]'
set yrange [0:105]
set logscale x
plot for [i=2:7] 'csv/reach_x.csv' using 1:i with linespoints lw 2
