# Run from the report folder: gnuplot figures/fig11.gp
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 900,450 font 'Sans,10'
} else {
  set terminal png size 900,450
}
set grid
set key outside right top
set termoption noenhanced
set datafile separator ','
set output 'figures/fig11.png'
set key autotitle columnheader
set title 'Fig. 11: NDT score (negated Eq. 4, lower is better), 3dtk 0_1'
set xlabel 'iteration'
set ylabel 'score'
plot 'csv/trace_ndt.csv' using 1:3 with linespoints lw 2 title 'NDT'
