# Run from the report folder: gnuplot figures/fig13.gp
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 900,450 font 'Sans,10'
} else {
  set terminal png size 900,450
}
set grid
set key outside right top
set termoption noenhanced
set datafile separator ','
set output 'figures/fig13.png'
set key autotitle columnheader
set title 'Fig. 13: normalised ML-NDT score, 3dtk 0_1'
set xlabel 'iteration'
set ylabel 'score / max |score|'
plot 'csv/trace_paper_newton.csv' using 1:4 with linespoints lw 2 title 'ML-NDT Newton, paper preset', 'csv/trace_paper_lm_scalar.csv' using 1:4 with linespoints lw 2 title 'ML-NDT LM with scalar s_k, paper preset', 'csv/trace_paper_lm.csv' using 1:4 with linespoints lw 2 title 'ML-NDT LM, paper preset', 'csv/trace_defaults_newton.csv' using 1:4 with linespoints lw 2 title 'ML-NDT Newton, defaults', 'csv/trace_defaults_lm.csv' using 1:4 with linespoints lw 2 title 'ML-NDT LM, defaults'
