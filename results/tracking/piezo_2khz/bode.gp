# bode.gp: Bode plot of the full-order and the reduced H-infinity controller
#
# Reads bode.csv.
# To re-render after editing, run inside this folder:
#     gnuplot bode.gp
# It writes bode.svg, bode.png and bode.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
set datafile separator ","
set logscale x
set grid
set key outside top center horizontal nobox noopaque samplen 2.5 spacing 1.1 width 1

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,760 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,760 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,5in font "Helvetica,10" }
  set output "bode.".ext
  set multiplot layout 2, 1 title "H-infinity feedback controller"
  set ylabel "magnitude (dB)"
  plot "bode.csv" using 1:2 with lines lw 2 lc rgb "black" title "full order (4)", \
       "bode.csv" using 1:4 with lines lw 1.5 dt 2 lc rgb "#d62728" title "reduced (3, stochastic)"
  set xlabel "frequency (Hz)"
  set ylabel "phase (degree)"
  plot "bode.csv" using 1:3 with lines lw 2 lc rgb "black" title "full order (4)", \
       "bode.csv" using 1:5 with lines lw 1.5 dt 2 lc rgb "#d62728" title "reduced (3, stochastic)"
  unset xlabel
  unset multiplot
}
unset output
