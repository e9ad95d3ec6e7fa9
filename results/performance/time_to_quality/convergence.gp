# convergence.gp: best-so-far fitness against function evaluations, one median
# line and one interquartile band per algorithm
#
# Reads convergence.dat (the finite rows of convergence.csv; per algorithm
# one index block for the median line and one for the band: evaluations q25 median q75).
# To re-render after editing, run inside this folder:
#     gnuplot convergence.gp
# It writes convergence.svg, convergence.png and convergence.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
set title "Convergence — time_to_quality (hammerstein(default.csv))"."\n"."median and interquartile range over 10 trials" noenhanced
set xlabel "Function evaluations"
set ylabel "Best-so-far fitness (SSE)"
set logscale xy
set format x "10^{%L}"
# The axis ends at the last evaluation rather than the next decade.
set xrange [1:*]
set autoscale xfixmax
set format y "10^{%L}"
noise_floor = 12044.9524  # SSE of the true parameters
# The first evaluations reach 3.215478086e+155: the axis stops at 3x the highest median after 1 % of the budget.
set yrange [*:119911949.2]
set label 1 "traces start above the axis, up to 3.22e+155" at graph 0.02, graph 0.96 left front noenhanced
set grid xtics ytics lt 1 lc rgb "#e0e0e0" lw 1
set key outside top center horizontal nobox noopaque samplen 2.5 spacing 1.1 width 1
set style fill transparent solid 0.25 noborder

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,560 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,560 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,3.75in font "Helvetica,10" }
  set output "convergence.".ext
  plot \
    "convergence.dat" index 1 using 1:2:4 with filledcurves lc rgb "#0072B2" notitle, \
    "convergence.dat" index 0 using 1:3 with lines lw 2 dt 1 lc rgb "#0072B2" title "IPOP-CMA-ES" noenhanced, \
    "convergence.dat" index 3 using 1:2:4 with filledcurves lc rgb "#D55E00" notitle, \
    "convergence.dat" index 2 using 1:3 with lines lw 2 dt 1 lc rgb "#D55E00" title "IPOP-CMA-ES+BOBYQA" noenhanced, \
    "convergence.dat" index 5 using 1:2:4 with filledcurves lc rgb "#009E73" notitle, \
    "convergence.dat" index 4 using 1:3 with lines lw 2 dt 1 lc rgb "#009E73" title "IPOP-CMA-ES+LM" noenhanced, \
    "convergence.dat" index 7 using 1:2:4 with filledcurves lc rgb "#CC79A7" notitle, \
    "convergence.dat" index 6 using 1:3 with lines lw 2 dt 1 lc rgb "#CC79A7" title "jSO+LM" noenhanced, \
    "convergence.dat" index 9 using 1:2:4 with filledcurves lc rgb "#E69F00" notitle, \
    "convergence.dat" index 8 using 1:3 with lines lw 2 dt 1 lc rgb "#E69F00" title "L-SHADE+LM" noenhanced, \
    "convergence.dat" index 11 using 1:2:4 with filledcurves lc rgb "#56B4E9" notitle, \
    "convergence.dat" index 10 using 1:3 with lines lw 2 dt 1 lc rgb "#56B4E9" title "AmFMMDE+LM" noenhanced, \
    "convergence.dat" index 13 using 1:2:4 with filledcurves lc rgb "#000000" notitle, \
    "convergence.dat" index 12 using 1:3 with lines lw 2 dt 1 lc rgb "#000000" title "DE+LM" noenhanced, \
    noise_floor with lines lw 1.5 dt 2 lc rgb "#404040" title "noise floor"
}
unset output
