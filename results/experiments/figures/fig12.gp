# Run from the report folder: gnuplot figures/fig12.gp
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1200,1100 font 'Sans,10'
} else {
  set terminal png size 1200,1100
}
set grid
set key outside right top
set termoption noenhanced
set datafile separator ','
set output 'figures/fig12.png'
set key autotitle columnheader
set multiplot layout 3,2 title 'Fig. 12: ML-NDT with LM, 3dtk 0_1'
set title 'ML-NDT LM with scalar s_k, paper preset: translation'
set xlabel 'iteration'
set ylabel 'parameter error [cm]'
plot 'csv/trace_paper_lm_scalar.csv' using 1:5 with linespoints title 'tx (lateral)', '' using 1:6 with linespoints title 'ty (vertical)', '' using 1:7 with linespoints title 'tz (forward)'
set title 'ML-NDT LM with scalar s_k, paper preset: rotation'
set ylabel 'parameter error [deg]'
plot 'csv/trace_paper_lm_scalar.csv' using 1:8 with linespoints title 'alpha', '' using 1:9 with linespoints title 'beta (heading)', '' using 1:10 with linespoints title 'gamma'
set title 'ML-NDT LM, paper preset: translation'
set xlabel 'iteration'
set ylabel 'parameter error [cm]'
plot 'csv/trace_paper_lm.csv' using 1:5 with linespoints title 'tx (lateral)', '' using 1:6 with linespoints title 'ty (vertical)', '' using 1:7 with linespoints title 'tz (forward)'
set title 'ML-NDT LM, paper preset: rotation'
set ylabel 'parameter error [deg]'
plot 'csv/trace_paper_lm.csv' using 1:8 with linespoints title 'alpha', '' using 1:9 with linespoints title 'beta (heading)', '' using 1:10 with linespoints title 'gamma'
set title 'ML-NDT LM, defaults: translation'
set xlabel 'iteration'
set ylabel 'parameter error [cm]'
plot 'csv/trace_defaults_lm.csv' using 1:5 with linespoints title 'tx (lateral)', '' using 1:6 with linespoints title 'ty (vertical)', '' using 1:7 with linespoints title 'tz (forward)'
set title 'ML-NDT LM, defaults: rotation'
set ylabel 'parameter error [deg]'
plot 'csv/trace_defaults_lm.csv' using 1:8 with linespoints title 'alpha', '' using 1:9 with linespoints title 'beta (heading)', '' using 1:10 with linespoints title 'gamma'
unset multiplot
