# diagnosis_candidates.gp: RMSE after adding each candidate effect: estimation and held-out
# bars, each marked at the current model's RMSE of the same kind
#
# Reads diagnosis_candidates.csv.
# To re-render after editing, run inside this folder:
#     gnuplot diagnosis_candidates.gp
# It writes diagnosis_candidates.svg, diagnosis_candidates.png and diagnosis_candidates.pdf: the plot commands
# sit once inside the loop over these three formats at the end.

set encoding utf8
bar = 0.36  # bar width; a group is two bars
current_estimation = 0.009154531087  # current model, estimation RMSE
current_heldout = 0.008359052418  # current model, held-out RMSE
sigma = 2.695630233e-05  # noise floor estimate

do for [ext in "svg png pdf"] {
  if (ext eq "svg") { set terminal svg size 900,760 font "Helvetica,12" background rgb "white" }
  if (ext eq "png") { set terminal pngcairo size 900,760 font "Helvetica,11" }
  if (ext eq "pdf") { set terminal pdfcairo size 6in,5in font "Helvetica,10" }
  set output "diagnosis_candidates.".ext
set datafile separator ','
set style fill solid 0.45 border
set boxwidth bar
set xrange [-0.6:11.6]
set lmargin 14
set xtics rotate by 45 right nomirror noenhanced
set key outside top center vertical maxrows 2
set grid ytics
set logscale y
set ylabel "RMSE [V]"
set title "RMSE after adding one effect to msd" noenhanced
plot 'diagnosis_candidates.csv' skip 1 using ($0 - 0.19):2:xtic(1) with boxes lc rgb '#0072B2' title 'estimation', \
     'diagnosis_candidates.csv' skip 1 using ($0 + 0.19):3 with boxes lc rgb '#D55E00' title 'held out', \
     'diagnosis_candidates.csv' skip 1 using ($0 - 0.37):(current_estimation):(bar):(0) with vectors nohead lw 3 lc rgb '#0072B2' title 'current, estimation', \
     'diagnosis_candidates.csv' skip 1 using ($0 + 0.01):(current_heldout):(bar):(0) with vectors nohead lw 3 lc rgb '#D55E00' title 'current, held out', \
     sigma with lines lw 2 dt 3 lc rgb '#808080' title 'noise floor σ'
}
unset output
