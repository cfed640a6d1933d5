if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 900,600 font 'Sans,10'
} else {
  set terminal png size 900,600
}
set grid
set key outside right top
set output 'docs/scaling.png'
set title 'Registration time against cloud size (median of 3 runs; MLNDT, CERES, GBS sampling)'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'points N (reference = input size)'
set ylabel 'time [ms]'
set key inside top left
set datafile separator ','
set xrange [6666.666667:1485000]
linear(x) = 0.002053216 * x
plot 'docs/scaling.csv' skip 1 using 1:2 with linespoints lw 2 pt 7 title 'map build (slope 0.74)', \
     '' skip 1 using 1:3 with linespoints lw 2 pt 5 title 'sampling (slope 0.86)', \
     '' skip 1 using 1:4 with linespoints lw 2 pt 9 title 'solve (slope 0.44)', \
     '' skip 1 using 1:5 with linespoints lw 2 pt 11 title 'total (slope 0.48)', \
     [10000:990000] linear(x) with lines dashtype 2 lc rgb 'gray40' lw 1.5 title 'slope 1 (∝ N)'
