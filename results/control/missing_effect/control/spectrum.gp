# spectrum.gp: Welch spectrum of the true (noise-free) error over the steady window, uncontrolled and controlled
#
# Reads spectrum.csv.
# To re-render after editing, run inside this folder:
#     gnuplot spectrum.gp
# It writes spectrum.svg, spectrum.png and spectrum.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
set datafile separator ","
set key outside top center horizontal nobox noopaque samplen 2.5 spacing 1.1 width 1
set grid
set xlabel "frequency (Hz)"
set ylabel "power (dB)"
set xrange [0:164.88]

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,760 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,760 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,5in font "Helvetica,10" }
  set output "spectrum.".ext
  plot "spectrum.csv" using 1:2 with lines lw 1.5 lt 1 dt 1 title "uncontrolled" noenhanced, \
       "spectrum.csv" using 1:3 with lines lw 1.5 lt 2 dt 1 title "FxNLMS, Ŝ = true actuator" noenhanced, \
       "spectrum.csv" using 1:4 with lines lw 1.5 lt 3 dt 1 title "FxNLMS, Ŝ = seed-chain fit" noenhanced, \
       "spectrum.csv" using 1:5 with lines lw 1.5 lt 4 dt 1 title "FxNLMS, Ŝ = discovered model" noenhanced, \
       "spectrum.csv" using 1:6 with lines lw 1.5 lt 5 dt 1 title "FxNLMS, Ŝ = beam only" noenhanced, \
       "spectrum.csv" using 1:7 with lines lw 1.5 lt 6 dt 1 title "VSS-FxLMS, Ŝ = true actuator" noenhanced, \
       "spectrum.csv" using 1:8 with lines lw 1.5 lt 7 dt 1 title "VSS-FxLMS, Ŝ = seed-chain fit" noenhanced, \
       "spectrum.csv" using 1:9 with lines lw 1.5 lt 8 dt 1 title "VSS-FxLMS, Ŝ = discovered model" noenhanced, \
       "spectrum.csv" using 1:10 with lines lw 1.5 lt 1 dt 2 title "VSS-FxLMS, Ŝ = beam only" noenhanced
}
unset output
