# fit_model_loops.gp: input-output (u-y) loops, measured and model
#
# Reads fit_model_loops.dat (one index block per segment: u y_measured y_model).
# To re-render after editing, run inside this folder:
#     gnuplot fit_model_loops.gp
# It writes fit_model_loops.svg, fit_model_loops.png and fit_model_loops.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
input_label = "Input u [V]"
output_label = "Output y [V]"
residual_label = "Residual\n" . "y − ŷ [V]"
# One panel per segment: the first `panels` index blocks of the data
# file, with tic spacing per panel (0: gnuplot's choice).
panels = 1
rows = 1
cols = 1
array segment[1] = [""]
array xstep[1] = [0.05]
array ystep[1] = [0.1]
set grid lt 1 lc rgb "#e0e0e0" lw 1
# Segment names stay readable where a loop runs under them.
set style textbox opaque noborder
# Tight axes plus a small margin, so no loop touches the frame.
set autoscale fix
set offsets graph 0.04, graph 0.04, graph 0.06, graph 0.06

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,760 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,760 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,5in font "Helvetica,10" }
  set output "fit_model_loops.".ext
  set multiplot layout rows, cols title "Best fit of model on Current model msd: u–y loops" noenhanced \
      margins char 9, char 2, char 3.5, char 3.5 spacing char 7, char 2
  do for [i=1:panels] {
    set label 1 segment[i] at graph 0.04, graph 0.9 left front boxed noenhanced
    set xlabel (i > panels - cols ? input_label : "")
    set ylabel ((i - 1) % cols == 0 ? output_label : "")
    if (xstep[i] > 0) { set xtics xstep[i] } else { set xtics autofreq }
    if (ystep[i] > 0) { set ytics ystep[i] } else { set ytics autofreq }
    # One key for all panels, in one row above the first.
    if (i == 1) { set key at screen 0.98, graph 1.02 right bottom vertical maxrows 1 \
                  samplen 2.5 } else { unset key }
    # Measured first, as a broad light band; the model thin on top of it.
    plot "fit_model_loops.dat" index i-1 using 1:2 with lines lw 4 lc rgb "#b4b4b4" title "measured", \
         "fit_model_loops.dat" index i-1 using 1:3 with lines lw 1 lc rgb "#0072B2" title "model"
  }
  unset multiplot
  unset label
}
unset output
