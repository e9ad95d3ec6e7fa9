# tracking_60-Hz.gp: reference, output and error at 60 Hz with 2DOF Hinf (3rd order)
#
# Reads tracking_60-Hz.csv.
# To re-render after editing, run inside this folder:
#     gnuplot tracking_60-Hz.gp
# It writes tracking_60-Hz.svg, tracking_60-Hz.png and tracking_60-Hz.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
set datafile separator ","
set key outside top center horizontal nobox noopaque samplen 2.5 spacing 1.1 width 1
set grid
set xtics 0.02
set ytics 5
set title "60 Hz, 2DOF Hinf (3rd order)" noenhanced
set xlabel "time in the scored window (s)"
set ylabel "displacement (µm)" noenhanced

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,560 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,560 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,3.75in font "Helvetica,10" }
  set output "tracking_60-Hz.".ext
  plot "tracking_60-Hz.csv" using 1:2 with lines lw 2 lc rgb "black" title "reference", \
       "tracking_60-Hz.csv" using 1:3 with lines lw 1.5 dt 2 lc rgb "#d62728" title "output", \
       "tracking_60-Hz.csv" using 1:4 with lines lw 1.5 lc rgb "#1f77b4" title "error"
}
unset output
