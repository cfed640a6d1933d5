# Run from the report folder: gnuplot figures/sampling.gp
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1200,500 font 'Sans,10'
} else {
  set terminal png size 1200,500
}
set grid
set key outside right top
set termoption noenhanced
set datafile separator ','
set output 'figures/sampling.png'
set key autotitle columnheader
set title 'Runs within tolerance against the sampled fraction (all data sets)'
set xlabel 'input sampled at random [%]'
set ylabel 'runs within tolerance [%]'
set logscale x
set xrange [0.8:40]
set yrange [0:105]
set xtics (1, 2, 5, 10, 20, 30)
plot for [i=2:4] 'csv/sampling_curve.csv' using 1:i with linespoints lw 2 dt 1, for [i=5:7] 'csv/sampling_curve.csv' using 1:i with linespoints lw 2 dt 2
