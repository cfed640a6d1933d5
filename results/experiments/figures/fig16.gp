# Run from the report folder: gnuplot figures/fig16.gp
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1200,1030 font 'Sans,10'
} else {
  set terminal png size 1200,1030
}
set grid
set key outside right top
set termoption noenhanced
set datafile separator ','
set output 'figures/fig16.png'
set key autotitle columnheader
set multiplot layout 3,2 title 'Fig. 16: ML-NDT (GBS) error, mulran'
set title 'paper preset, mulran: translation'
set xlabel 'pair index (consecutive pairs)'
set ylabel 'error [cm]'
plot 'csv/fig16_paper.csv' using 1:3 with linespoints title 'tx (lateral)', '' using 1:4 with linespoints title 'ty (vertical)', '' using 1:5 with linespoints title 'tz (forward)'
set title 'paper preset, mulran: rotation'
set ylabel 'error [deg]'
plot 'csv/fig16_paper.csv' using 1:6 with linespoints title 'alpha', '' using 1:7 with linespoints title 'beta (heading)', '' using 1:8 with linespoints title 'gamma'
set title 'defaults, mulran: translation'
set xlabel 'pair index (consecutive pairs)'
set ylabel 'error [cm]'
plot 'csv/fig16_defaults.csv' using 1:3 with linespoints title 'tx (lateral)', '' using 1:4 with linespoints title 'ty (vertical)', '' using 1:5 with linespoints title 'tz (forward)'
set title 'defaults, mulran: rotation'
set ylabel 'error [deg]'
plot 'csv/fig16_defaults.csv' using 1:6 with linespoints title 'alpha', '' using 1:7 with linespoints title 'beta (heading)', '' using 1:8 with linespoints title 'gamma'
set title 'defaults, prior uncertainty given, mulran: translation'
set xlabel 'pair index (consecutive pairs)'
set ylabel 'error [cm]'
plot 'csv/fig16_defaults_known.csv' using 1:3 with linespoints title 'tx (lateral)', '' using 1:4 with linespoints title 'ty (vertical)', '' using 1:5 with linespoints title 'tz (forward)'
set title 'defaults, prior uncertainty given, mulran: rotation'
set ylabel 'error [deg]'
plot 'csv/fig16_defaults_known.csv' using 1:6 with linespoints title 'alpha', '' using 1:7 with linespoints title 'beta (heading)', '' using 1:8 with linespoints title 'gamma'
unset multiplot
