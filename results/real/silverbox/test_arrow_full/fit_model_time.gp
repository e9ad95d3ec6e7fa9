# fit_model_time.gp: measured and model output over time (top), residual (bottom)
#
# Reads fit_model_time.dat (400 bins of samples: t, then min and max of y, model, residual).
# To re-render after editing, run inside this folder:
#     gnuplot fit_model_time.gp
# It writes fit_model_time.svg, fit_model_time.png and fit_model_time.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
input_label = "Input u [V]"
output_label = "Output y [V]"
residual_label = "Residual\n" . "y − ŷ [V]"

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,760 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,760 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,5in font "Helvetica,10" }
  set output "fit_model_time.".ext
  set datafile separator whitespace
  set multiplot
  set yrange [*:*]
  set autoscale fix
  set lmargin 10
  set rmargin 2
  set origin 0, 0.38
  set size 1, 0.62
  set tmargin 4
  set bmargin 0.5
  set title "Best fit of model on Model duffing,offset against test_arrow_full.csv" noenhanced offset 0, 1.2
  set offsets 0, 0, graph 0.05, graph 0.05
  set format x ""
  unset xlabel
  set ylabel output_label
  set ytics -0.2, 0.2, 0.275761748
  set key at graph 1, graph 1.01 right bottom horizontal samplen 2.5
  plot "fit_model_time.dat" using 1:2:3 with filledcurves fc rgb "#b4b4b4" notitle, \
       "fit_model_time.dat" using 1:2 with lines lw 4 lc rgb "#b4b4b4" title "measured (range per bin)", \
       "fit_model_time.dat" using 1:3 with lines lw 4 lc rgb "#b4b4b4" notitle, \
       "fit_model_time.dat" using 1:4 with lines lw 1 lc rgb "#0072B2" title "model", \
       "fit_model_time.dat" using 1:5 with lines lw 1 lc rgb "#0072B2" notitle
  unset label
  unset title
  unset key
  set origin 0, 0
  set size 1, 0.38
  set tmargin 0.5
  set bmargin 3.2
  set format x "% h"
  set xlabel "Time t [s]"
  set ylabel residual_label
  set yrange [-0.004820704203:0.004820704203]
  set ytics -0.002, 0.002, 0.002
  plot "fit_model_time.dat" using 1:6:7 with filledcurves fc rgb "#D55E00" notitle, \
       "fit_model_time.dat" using 1:6 with lines lw 1 lc rgb "#D55E00" notitle, \
       "fit_model_time.dat" using 1:7 with lines lw 1 lc rgb "#D55E00" notitle
  unset multiplot
  unset arrow
}
unset output
