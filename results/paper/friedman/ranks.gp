# ranks.gp: Friedman average rank of each algorithm over the data sets,
# with Nemenyi critical-difference bars
#
# Reads ranks.dat (position average_rank label, best first).
# To re-render after editing, run inside this folder:
#     gnuplot ranks.gp
# It writes ranks.svg, ranks.png and ranks.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
set title "Friedman average ranks over 6 data sets"."\n"."bars: average rank ± CD/2, CD = 4.905 (Nemenyi, α = 0.05); bars that do not overlap differ" noenhanced
set xlabel "Average rank (1 = best)"
set xrange [-0.9856796588:11.65234633]
set xtics 1, 1, 9
set yrange [9.5:0.5]
set ytics ("jSO" 1, "IPOP-CMA-ES" 2, "AmFMMDE" 3, "MEDE" 4, "HJaya" 5, "PSO" 6, "GA" 7, "DE" 8, "DETVSF" 9) noenhanced
set grid xtics lt 1 lc rgb "#e0e0e0" lw 1
unset key

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,560 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,560 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,3.75in font "Helvetica,10" }
  set output "ranks.".ext
  plot "ranks.dat" using 2:1:($2-2.452346325):($2+2.452346325) with xerrorbars pointtype 7 pointsize 1.2 linewidth 2 lc rgb "#1f77b4"
}
unset output
