# loop_30-Hz.gp: hysteresis loop at 30 Hz: measured and modelled output against the input
#
# Reads loop_30-Hz.csv.
# To re-render after editing, run inside this folder:
#     gnuplot loop_30-Hz.gp
# It writes loop_30-Hz.svg, loop_30-Hz.png and loop_30-Hz.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
set datafile separator ","
set key outside top center horizontal nobox noopaque samplen 2.5 spacing 1.1 width 1
set grid
set title "30 Hz" noenhanced
set xlabel "input (V)" noenhanced
set ylabel "output (µm)" noenhanced
set xtics 20
set ytics 2

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,560 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,560 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,3.75in font "Helvetica,10" }
  set output "loop_30-Hz.".ext
  plot "loop_30-Hz.csv" using 1:2 with lines lw 2 lc rgb "black" title "measured", \
       "loop_30-Hz.csv" using 1:3 with lines lw 1.5 dt 2 lc rgb "#d62728" title "SVR"
}
unset output
