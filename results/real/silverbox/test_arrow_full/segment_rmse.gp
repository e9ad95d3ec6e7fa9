# segment_rmse.gp: RMSE per segment (bars; colour: estimation / held out / mixed),
# noise floor as a dashed line
#
# Reads segment_rmse.dat (index segment rmse part).
# To re-render after editing, run inside this folder:
#     gnuplot segment_rmse.gp
# It writes segment_rmse.svg, segment_rmse.png and segment_rmse.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
rmse_label = "RMSE [V]"
sigma = 3.040758659e-05  # noise floor estimate
set title "Error per segment — Model duffing,offset against test_arrow_full.csv" noenhanced
set ylabel rmse_label
set yrange [0:0.0003254989517]
set xrange [-0.6:0.6]
set style fill solid 0.85 border rgb "#404040"
set boxwidth 0.7
# Many segments: names upright, ending at their bar, so none leaves the page.
set xtics nomirror noenhanced
set grid ytics lt 1 lc rgb "#e0e0e0" lw 1
set key outside top center horizontal nobox noopaque samplen 2.5 spacing 1.1 width 1
  set ytics 0, 0.0001, 0.0003013879183

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,560 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,560 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,3.75in font "Helvetica,10" }
  set output "segment_rmse.".ext
  plot "segment_rmse.dat" using 1:(strcol(4) eq "estimation" ? $3 : NaN):xtic(2) with boxes fc rgb "#0072B2" title "test", \
       sigma with lines dt 2 lw 2 lc rgb "#000000" title "noise σ"
}
unset output
