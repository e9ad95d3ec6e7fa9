# fit_model_time.gp: measured and model output over time (top), residual (bottom)
#
# Reads fit_model_time.dat (400 bins of samples: t, then min and max of y, model, residual).
# To re-render after editing, run inside this folder:
#     gnuplot fit_model_time.gp
# It writes fit_model_time.svg, fit_model_time.png and fit_model_time.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
input_label = "Input u [V]"
output_label = "Output y [µm]"
residual_label = "Residual\n" . "y − ŷ [µm]"

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
  set title "Best fit of model on Model svr_hammerstein(m = 4, n = 4, ARX 5/5) against test.csv" noenhanced offset 0, 1.2
  set offsets 0, 0, graph 0.45, graph 0.05
  set label "1 Hz" at 2.5, graph 0.92 center noenhanced
  set arrow from 5, graph 0 to 5, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "5 Hz" at 5.5, graph 0.81 center noenhanced
  set arrow from 6, graph 0 to 6, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "10 Hz" at 6.25, graph 0.92 center noenhanced
  set arrow from 6.5, graph 0 to 6.5, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "20 Hz" at 6.625, graph 0.81 center noenhanced
  set arrow from 6.75, graph 0 to 6.75, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "30 Hz" at 6.83325, graph 0.92 center noenhanced
  set arrow from 6.9165, graph 0 to 6.9165, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "40 Hz" at 6.979, graph 0.81 center noenhanced
  set arrow from 7.0415, graph 0 to 7.0415, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "50 Hz" at 7.0915, graph 0.92 center noenhanced
  set arrow from 7.1415, graph 0 to 7.1415, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "60 Hz" at 7.18325, graph 0.81 center noenhanced
  set arrow from 7.225, graph 0 to 7.225, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "70 Hz" at 7.26075, graph 0.92 center noenhanced
  set arrow from 7.2965, graph 0 to 7.2965, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "80 Hz" at 7.32775, graph 0.81 center noenhanced
  set arrow from 7.359, graph 0 to 7.359, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "90 Hz" at 7.38675, graph 0.92 center noenhanced
  set arrow from 7.4145, graph 0 to 7.4145, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "100 Hz" at 7.4395, graph 0.81 center noenhanced
  set arrow from 7.4645, graph 0 to 7.4645, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "10/30/50/70/90 Hz" at 7.7145, graph 0.92 center noenhanced
  set arrow from 7.9645, graph 0 to 7.9645, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "30/60/90 Hz" at 8.04775, graph 0.81 center noenhanced
  set arrow from 8.131, graph 0 to 8.131, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "10/20/40 Hz" at 8.381, graph 0.92 center noenhanced
  set arrow from 8.631, graph 0 to 8.631, graph 1 nohead lc rgb "#a0a0a0" dt 2 back
  set label "20/40/60/80/100 Hz" at 8.75575, graph 0.81 center noenhanced
  set format x ""
  unset xlabel
  set ylabel output_label
  set ytics 0, 5, 17.48786398
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
  set yrange [-2.343915956:2.343915956]
  set ytics -2, 2, 2
  plot "fit_model_time.dat" using 1:6:7 with filledcurves fc rgb "#D55E00" notitle, \
       "fit_model_time.dat" using 1:6 with lines lw 1 lc rgb "#D55E00" notitle, \
       "fit_model_time.dat" using 1:7 with lines lw 1 lc rgb "#D55E00" notitle
  unset multiplot
  unset arrow
}
unset output
