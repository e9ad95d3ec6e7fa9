# boxplot.gp: final best fitness of the trials, one box per algorithm
#
# Reads boxplot.dat (one index block per algorithm: final).
# To re-render after editing, run inside this folder:
#     gnuplot boxplot.gp
# It writes boxplot.svg, boxplot.png and boxplot.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
set title "Final fitness — demo (hammerstein(default.csv))"."\n"."box: quartiles, whiskers: 1.5 IQR, over 10 trials" noenhanced
set ylabel "Final best fitness (SSE)"
set xtics ("DE" 1) noenhanced
set xrange [0.4:1.6]
set style fill solid 0.35 border
set style boxplot outliers pointtype 7
set boxwidth 0.5
set grid ytics lt 1 lc rgb "#e0e0e0" lw 1
unset key
set logscale y

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,560 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,560 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,3.75in font "Helvetica,10" }
  set output "boxplot.".ext
  plot \
    "boxplot.dat" index 0 using (1):1 with boxplot lc rgb "#0072B2"
}
unset output
