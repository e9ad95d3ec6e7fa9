# boxplot.gp: final best fitness of the trials, one box per algorithm
#
# Reads boxplot.dat (one index block per algorithm: final).
# To re-render after editing, run inside this folder:
#     gnuplot boxplot.gp
# It writes boxplot.svg, boxplot.png and boxplot.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
set title "Final fitness — time_to_quality (hammerstein(default.csv))"."\n"."box: quartiles, whiskers: 1.5 IQR, over 10 trials" noenhanced
set ylabel "Final best fitness (SSE)"
set xtics ("IPOP-CMA-ES" 1, "IPOP-CMA-ES+BOBYQA" 2, "IPOP-CMA-ES+LM" 3, "jSO+LM" 4, "L-SHADE+LM" 5, "AmFMMDE+LM" 6, "DE+LM" 7) noenhanced rotate by 45 right
set xrange [0.4:7.6]
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
    "boxplot.dat" index 0 using (1):1 with boxplot lc rgb "#0072B2", \
    "boxplot.dat" index 1 using (2):1 with boxplot lc rgb "#D55E00", \
    "boxplot.dat" index 2 using (3):1 with boxplot lc rgb "#009E73", \
    "boxplot.dat" index 3 using (4):1 with boxplot lc rgb "#CC79A7", \
    "boxplot.dat" index 4 using (5):1 with boxplot lc rgb "#E69F00", \
    "boxplot.dat" index 5 using (6):1 with boxplot lc rgb "#56B4E9", \
    "boxplot.dat" index 6 using (7):1 with boxplot lc rgb "#000000"
}
unset output
