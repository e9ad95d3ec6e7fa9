#!/usr/bin/env bash
# Seed 002's Table 1 on a simulated piezo stack actuator: makes the data
# (hystbench simulate), fits the grey-box catalog model on the training
# record (hystbench fit) and identifies and scores the SVR Hammerstein-like
# model beside it (hystbench svr benchmarks/experiments/svr_piezo.json).
#
#   benchmarks/svr_piezo.sh [OUT_DIR]
#
# OUT_DIR defaults to results/svr; the data go to OUT_DIR/data (not
# committed: regenerated bit for bit from the seeds below). Needs a built
# build/hystbench (or HYSTBENCH=path). Takes about 2 minutes on 2 cores.
set -euo pipefail
out=${1:-results/svr}
hystbench=${HYSTBENCH:-build/hystbench}
experiment=benchmarks/experiments/svr_piezo.json
mkdir -p "$out/data" "$out/greybox"
# The experiment names its files under results/svr; elsewhere, a copy names $out.
if [[ "$out" != results/svr ]]; then
  sed "s#results/svr/#$out/#g" "$experiment" > "$out/svr_piezo.json"
  experiment="$out/svr_piezo.json"
fi
HYSTBENCH="$hystbench" benchmarks/svr_piezo_data.sh "$out/data"
"$hystbench" fit --data "$out/data/train.csv" --model hysteresis,asymmetry,msd --input-unit V \
  --output-unit µm --out "$out/greybox" --force | tee "$out/greybox/fit.log"
"$hystbench" svr "$experiment" --out "$out/piezo" --force | tee "$out/piezo.log"
# Where the SVR model fails, as for a catalog fit: breakdowns and residual signatures.
"$hystbench" compare --data "$out/data/test.csv" --fit "$out/piezo/svr_model.json" --input-unit V \
  --output-unit µm --out "$out/compare" --force | tee "$out/compare.log"
