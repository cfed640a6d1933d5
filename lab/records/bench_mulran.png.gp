if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1100,840 font 'Sans,10'
} else {
  set terminal png size 1100,840
}
set grid
set key outside right top
set output 'bench_mulran.png'
set termoption noenhanced
set logscale xy
set multiplot layout 2,1
set xlabel 'median time per registration [ms]'
set ylabel 'mean translation error [m]'
set title 'mulran_kaist03_keyframes/prior: one point per configuration, Pareto front joined'
plot 'bench_mulran.png.dat' index 0 using 1:2 with points pt 7 ps 0.8 lc rgb 'gray50' title 'configuration', \
  'bench_mulran.png.dat' index 0 using 1:($3 > 0 ? $2 : 1/0) with linespoints pt 7 lw 2 lc rgb 'red' title 'Pareto front', \
  'bench_mulran.png.dat' index 0 using 1:($3 > 0 ? $2 : 1/0):4 with labels offset 0.5,0.6 left font ',8' notitle
set title 'mulran_kaist03_keyframes/offsets: one point per configuration, Pareto front joined'
plot 'bench_mulran.png.dat' index 1 using 1:2 with points pt 7 ps 0.8 lc rgb 'gray50' title 'configuration', \
  'bench_mulran.png.dat' index 1 using 1:($3 > 0 ? $2 : 1/0) with linespoints pt 7 lw 2 lc rgb 'red' title 'Pareto front', \
  'bench_mulran.png.dat' index 1 using 1:($3 > 0 ? $2 : 1/0):4 with labels offset 0.5,0.6 left font ',8' notitle
unset multiplot
