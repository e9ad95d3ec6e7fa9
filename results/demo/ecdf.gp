# ecdf.gp: fraction of trials that reached the target fitness
# against function evaluations, one step line per algorithm
#
# Reads ecdf.dat (ecdf.csv as one index block per algorithm: evaluations fraction).
# To re-render after editing, run inside this folder:
#     gnuplot ecdf.gp
# It writes ecdf.svg, ecdf.png and ecdf.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
set title "Runtime ECDF — demo (hammerstein(default.csv))"."\n"."fraction of 10 trials with best fitness <= 1.217e+04" noenhanced
set xlabel "Function evaluations"
set ylabel "Share of trials at target"
set logscale x
set format x "10^{%L}"
set autoscale xfix
set offsets graph 0.05, graph 0.02, 0, 0
set yrange [0:1.02]
set grid xtics ytics lt 1 lc rgb "#e0e0e0" lw 1
set key outside top center horizontal nobox noopaque samplen 2.5 spacing 1.1 width 1

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,560 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,560 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,3.75in font "Helvetica,10" }
  set output "ecdf.".ext
  plot \
    "ecdf.dat" index 0 using 1:2 with steps lw 2 dt 1 lc rgb "#0072B2" title "DE" noenhanced
}
unset output
