# step_size.gp: step size mu(n) of every controlled run
#
# Reads traces.csv (first noise seed, every 20th sample).
# To re-render after editing, run inside this folder:
#     gnuplot step_size.gp
# It writes step_size.svg, step_size.png and step_size.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
set datafile separator ","
set key outside top center horizontal nobox noopaque samplen 2.5 spacing 1.1 width 1
set grid
set xlabel "time (s)"
set ylabel "step size"
set logscale y

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,560 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,560 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,3.75in font "Helvetica,10" }
  set output "step_size.".ext
  plot "traces.csv" using 1:6 with lines lw 1.5 lt 2 dt 1 title "FxLMS" noenhanced, \
       "traces.csv" using 1:9 with lines lw 1.5 lt 3 dt 1 title "FxNLMS" noenhanced, \
       "traces.csv" using 1:12 with lines lw 1.5 lt 4 dt 1 title "VSS-FxLMS" noenhanced, \
       "traces.csv" using 1:15 with lines lw 1.5 lt 5 dt 1 title "VSS-FxLMS, mu_max 0.01" noenhanced, \
       "traces.csv" using 1:18 with lines lw 1.5 lt 6 dt 1 title "VSS Kwong" noenhanced, \
       "traces.csv" using 1:21 with lines lw 1.5 lt 7 dt 1 title "VSS Aboulnasr" noenhanced
}
unset output
