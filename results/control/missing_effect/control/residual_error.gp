# residual_error.gp: 1 s moving RMS of the true residual error, dB re the uncontrolled steady level
#
# Reads traces.csv (first noise seed, every 20th sample).
# To re-render after editing, run inside this folder:
#     gnuplot residual_error.gp
# It writes residual_error.svg, residual_error.png and residual_error.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
set datafile separator ","
set key outside top center horizontal nobox noopaque samplen 2.5 spacing 1.1 width 1
set grid
set xlabel "time (s)"
set ylabel "residual RMS (dB)"

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,760 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,760 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,5in font "Helvetica,10" }
  set output "residual_error.".ext
  plot "traces.csv" using 1:2 with lines lw 1.5 lt 1 dt 1 title "uncontrolled" noenhanced, \
       "traces.csv" using 1:5 with lines lw 1.5 lt 2 dt 1 title "FxNLMS, Ŝ = true actuator" noenhanced, \
       "traces.csv" using 1:8 with lines lw 1.5 lt 3 dt 1 title "FxNLMS, Ŝ = seed-chain fit" noenhanced, \
       "traces.csv" using 1:11 with lines lw 1.5 lt 4 dt 1 title "FxNLMS, Ŝ = discovered model" noenhanced, \
       "traces.csv" using 1:14 with lines lw 1.5 lt 5 dt 1 title "FxNLMS, Ŝ = beam only" noenhanced, \
       "traces.csv" using 1:17 with lines lw 1.5 lt 6 dt 1 title "VSS-FxLMS, Ŝ = true actuator" noenhanced, \
       "traces.csv" using 1:20 with lines lw 1.5 lt 7 dt 1 title "VSS-FxLMS, Ŝ = seed-chain fit" noenhanced, \
       "traces.csv" using 1:23 with lines lw 1.5 lt 8 dt 1 title "VSS-FxLMS, Ŝ = discovered model" noenhanced, \
       "traces.csv" using 1:26 with lines lw 1.5 lt 1 dt 2 title "VSS-FxLMS, Ŝ = beam only" noenhanced
}
unset output
