# correlation.gp: residual autocorrelation (top) and input-residual cross-correlation
# (bottom) with the 99 % band ±2.58/√N
#
# Reads correlation.dat (index 0: ACF, index 1: CCF; lag value).
# To re-render after editing, run inside this folder:
#     gnuplot correlation.gp
# It writes correlation.svg, correlation.png and correlation.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
acf_bound = 0.01443391936
ccf_bound = 0.01443391936
set grid lt 1 lc rgb "#e0e0e0" lw 1
set key outside top center horizontal nobox noopaque samplen 2.5 spacing 1.1 width 1
set ylabel "Correlation"
set xtics 5
set mxtics 5

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,760 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,760 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,5in font "Helvetica,10" }
  set output "correlation.".ext
  set multiplot layout 2, 1 title "Residual tests — Model duffing,offset against test_arrow_no_extrapolation.csv" noenhanced
  set title "Autocorrelation of the residual r_{ee}(τ)"
  set yrange [-0.8368500136:0.8368500136]
  set xrange [0.5:25.5]
  plot "correlation.dat" index 0 using 1:2 with impulses lw 3 lc rgb "#0072B2" notitle, \
       "" index 0 using 1:2 with points pt 7 ps 0.5 lc rgb "#0072B2" notitle, \
       acf_bound with lines dt 2 lw 1.5 lc rgb "#D55E00" title "99 % band", \
       -acf_bound with lines dt 2 lw 1.5 lc rgb "#D55E00" notitle, \
       0 with lines lw 1 lc rgb "#404040" notitle
  set xlabel "Lag τ [samples]  (τ > 0: residual against past input)"
  set title "Cross-correlation of input and residual r_{ue}(τ)"
  set yrange [-0.05764720381:0.05764720381]
  set xrange [-25.5:25.5]
  plot "correlation.dat" index 1 using 1:2 with impulses lw 3 lc rgb "#0072B2" notitle, \
       "" index 1 using 1:2 with points pt 7 ps 0.5 lc rgb "#0072B2" notitle, \
       ccf_bound with lines dt 2 lw 1.5 lc rgb "#D55E00" title "99 % band", \
       -ccf_bound with lines dt 2 lw 1.5 lc rgb "#D55E00" notitle, \
       0 with lines lw 1 lc rgb "#404040" notitle
  unset xlabel
  unset multiplot
}
unset output
