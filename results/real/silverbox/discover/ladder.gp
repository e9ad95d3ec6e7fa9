# ladder.gp: the error falling as effects are added (σ: the noise sd)
#
# Reads ladder.csv.
# To re-render after editing, run inside this folder:
#     gnuplot ladder.gp
# It writes ladder.svg, ladder.png and ladder.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,560 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,560 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,3.75in font "Helvetica,10" }
  set output "ladder.".ext
set datafile separator ','
set key outside top center horizontal nobox noopaque samplen 2.5 spacing 1.1 width 1
set grid
set logscale y
set xtics noenhanced
set offsets 0.3, 0.3, 0, 0
set xlabel 'effect added at each step'
set ylabel "RMSE [V]"
set title "Discovery from msd" noenhanced
sigma = 2.713327169e-05
truth = NaN
plot 'ladder.csv' using 1:3:xtic(2) with linespoints lw 2 pt 7 title 'estimation', \
     '' using 1:4 with linespoints lw 2 pt 5 title 'held out', \
     sigma with lines dt 2 lw 2 lc rgb '#808080' title 'σ estimated'
}
unset output
