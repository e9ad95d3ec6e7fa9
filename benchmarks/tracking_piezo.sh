#!/usr/bin/env bash
# Seed 002's Table 2 on the simulated piezo stack of the SVR work (hystbench
# track): inverse compensation and the 2DOF H-infinity controller built from
# a model identified there, with the uncertainty weight measured on its test
# record, against a PI baseline.
#   piezo/      the grey-box model (results/svr/greybox/fit.json), loop at 10 kHz as in the seed
#   piezo_2khz/ the same at 2 kHz, the rate of the SVR model
#   piezo_svr/  the SVR model (results/svr/piezo/svr_model.json) at 2 kHz
#   fixed_order/ every optimizer tuning a 3rd-order H-infinity controller directly
#               (hystbench run benchmarks/experiments/fixed_order_hinf.json)
#
#   benchmarks/tracking_piezo.sh [OUT_DIR]      # default results/tracking
#
# The test record is not committed: the experiments simulate it when missing
# (benchmarks/experiments/svr_piezo/records.json), bit for bit.
# Needs a built build/hystbench (or HYSTBENCH=path). About a minute on 2 cores.
set -euo pipefail
out=${1:-results/tracking}
hystbench=${HYSTBENCH:-build/hystbench}
mkdir -p "$out"
for run in piezo piezo_2khz piezo_svr; do
  "$hystbench" track "benchmarks/experiments/tracking_$run.json" --out "$out/$run" --force | tee "$out/$run.log"
done
"$hystbench" run benchmarks/experiments/fixed_order_hinf.json --out "$out/fixed_order" --force | tee "$out/fixed_order.log"
