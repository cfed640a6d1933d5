# Run from the report folder: gnuplot figures/fig17.gp
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1200,450 font 'Sans,10'
} else {
  set terminal png size 1200,450
}
set grid
set key outside right top
set termoption noenhanced
set datafile separator ','
set output 'figures/fig17.png'
set key autotitle columnheader
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set boxwidth 0.9
set key top left inside
set multiplot layout 1,2 title 'Fig. 17: mean |error|, consecutive pairs of mulran'
set title 'translation'
set ylabel 'mean |error| [cm]'
plot 'csv/fig17.csv' every ::0::2 using 2:xtic(1) title 'prior', '' every ::0::2 using 3 title 'NDT', '' every ::0::2 using 4 title 'ML-NDT paper preset', '' every ::0::2 using 5 title 'ML-NDT defaults'
set title 'rotation'
set ylabel 'mean |error| [deg]'
plot 'csv/fig17.csv' every ::3::5 using 2:xtic(1) title 'prior', '' every ::3::5 using 3 title 'NDT', '' every ::3::5 using 4 title 'ML-NDT paper preset', '' every ::3::5 using 5 title 'ML-NDT defaults'
unset multiplot
