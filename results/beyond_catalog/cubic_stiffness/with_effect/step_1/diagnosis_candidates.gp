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
current_estimation = 0.01013582477  # current model, estimation RMSE
current_heldout = 0.01002419416  # current model, held-out RMSE
sigma = 0.009756945923  # noise floor estimate
# No candidate effect was tried: nothing to draw.
