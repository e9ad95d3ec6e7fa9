# diagnosis_candidates.gp: RMSE after adding each candidate effect
#
# Reads diagnosis_candidates.csv.
# To re-render after editing, run inside this folder:
#     gnuplot diagnosis_candidates.gp
# It writes diagnosis_candidates.svg, diagnosis_candidates.png and diagnosis_candidates.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,560 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,560 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,3.75in font "Helvetica,10" }
  set output "diagnosis_candidates.".ext
set datafile separator ','
set style data histograms
set xrange [-0.6:*]
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set xtics rotate by -35 noenhanced
set key outside top center horizontal
set grid ytics
set logscale y
set ylabel "RMSE [m]"
set title "Adding one effect to feedback_hysteresis" noenhanced
current = 7.37034503e-06
sigma = 7.420350323e-06
plot 'diagnosis_candidates.csv' using 2:xtic(1) title 'estimation RMSE after', \
     '' using 3 title 'held-out RMSE after', \
     current with lines lw 2 dt 2 lc rgb 'black' title 'current model', \
     sigma with lines lw 2 dt 3 lc rgb '#808080' title 'noise floor σ'
}
unset output
