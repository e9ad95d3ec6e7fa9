# residual.gp: residual over time; held-out spans shaded, segment boundaries dashed,
# noise floor as dotted lines
#
# Reads residual.dat (t residual).
# To re-render after editing, run inside this folder:
#     gnuplot residual.gp
# It writes residual.svg, residual.png and residual.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
residual_label = "Residual y − ŷ [V]"
sigma = 1.698489e-05  # noise floor estimate
set title "Residual — Model duffing,offset against test_arrow_no_extrapolation.csv" noenhanced
set xlabel "Time t [s]"
set ylabel residual_label
set grid lt 1 lc rgb "#e0e0e0" lw 1
set autoscale xfix
# Room above the data for the segment names; the key sits above the frame.
set offsets 0, 0, graph 0.2, graph 0.05
set key outside top center horizontal nobox noopaque samplen 2.5 spacing 1.1 width 1
  set ytics -0.001, 0.001, 0.002178714026

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,560 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,560 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,3.75in font "Helvetica,10" }
  set output "residual.".ext
  plot "residual.dat" using 1:2 with lines lw 1 lc rgb "#D55E00" title "residual y − ŷ", \
       sigma with lines dt 3 lw 1.5 lc rgb "#000000" title "± noise σ", \
       -sigma with lines dt 3 lw 1.5 lc rgb "#000000" notitle
}
unset output
