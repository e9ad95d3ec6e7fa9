# relative_error.gp: free-run relative error RE of each model by test signal
#
# Reads relative_error.csv.
# To re-render after editing, run inside this folder:
#     gnuplot relative_error.gp
# It writes relative_error.svg, relative_error.png and relative_error.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
set datafile separator ","
set key outside top center horizontal nobox noopaque samplen 2.5 spacing 1.1 width 1
set grid
set xtics rotate by 45 right noenhanced
set ylabel "RE (%)"
set logscale y
set xrange [-0.5:15.5]

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,560 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,560 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,3.75in font "Helvetica,10" }
  set output "relative_error.".ext
  plot "relative_error.csv" using 1:3:xtic(2) with linespoints lw 1.5 pt 7 lc rgb "#d62728" title "SVR"
}
unset output
